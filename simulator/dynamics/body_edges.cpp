#include "simulator/dynamics/body_edges.h"

#include <algorithm>
#include <limits>
#include <map>

namespace viscera::sim {

std::span<const std::array<int, 2>> BodyEdges::edges() const {
  return distance_ != nullptr ? std::span<const std::array<int, 2>>(distance_->terms().edges)
                              : std::span<const std::array<int, 2>>(springs_->springs().knots);
}

std::span<double> BodyEdges::rest_lengths() const {
  return distance_ != nullptr ? std::span<double>(distance_->mutable_terms().rest_length)
                              : std::span<double>(springs_->mutable_springs().rest_length);
}

const BodyModel& BodyEdges::model() const {
  return distance_ != nullptr ? distance_->model() : springs_->model();
}

std::vector<double> BodyEdges::material_limit(double core::Material::*limit, int first) const {
  const BodyModel& body = model();
  double weakest = std::numeric_limits<double>::infinity();
  for (const auto& material : body.materials)
    weakest = std::min(weakest, material.*limit);
  std::map<std::pair<int, int>, double> per_edge;
  for (std::size_t t = 0; t < body.mesh.tets.size(); ++t) {
    const double value = body.material_of(static_cast<int>(t)).*limit;
    const auto& tet = body.mesh.tets[t];
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const auto key = std::minmax(tet[i], tet[j]);
        const auto it = per_edge.find(key);
        if (it == per_edge.end())
          per_edge.emplace(key, value);
        else
          it->second = std::min(it->second, value);
      }
  }
  std::vector<double> out;
  out.reserve(edges().size());
  for (const auto& e : edges()) {
    const auto it = per_edge.find(std::minmax(e[0] - first, e[1] - first));
    out.push_back(it != per_edge.end() ? it->second : weakest);
  }
  return out;
}

}  // namespace viscera::sim
