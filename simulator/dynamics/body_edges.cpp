#include "simulator/dynamics/body_edges.h"

#include <algorithm>
#include <cstdint>
#include <limits>

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
  double weakest = std::numeric_limits<double>::infinity(), strongest = -weakest;
  for (const auto& material : body.materials) {
    weakest = std::min(weakest, material.*limit);
    strongest = std::max(strongest, material.*limit);
  }
  // One value over the body (one material, or layers that agree): every edge has it.
  if (!(weakest < strongest)) return std::vector<double>(edges().size(), weakest);
  // Layers that differ: each tet edge keyed by its two local nodes, with the tet's value; the
  // sorted keys put an edge's tets side by side, so its smallest value comes first.
  struct Entry {
    std::uint64_t key;
    double value;
  };
  const auto key_of = [](int a, int b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
           static_cast<std::uint32_t>(std::max(a, b));
  };
  std::vector<Entry> per_tet_edge;
  per_tet_edge.reserve(6 * body.mesh.tets.size());
  for (std::size_t t = 0; t < body.mesh.tets.size(); ++t) {
    const double value = body.material_of(static_cast<int>(t)).*limit;
    const auto& tet = body.mesh.tets[t];
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        per_tet_edge.push_back({key_of(tet[i], tet[j]), value});
  }
  std::sort(per_tet_edge.begin(), per_tet_edge.end(), [](const Entry& a, const Entry& b) {
    return a.key < b.key || (a.key == b.key && a.value < b.value);
  });
  std::vector<double> out;
  out.reserve(edges().size());
  for (const auto& e : edges()) {
    const std::uint64_t key = key_of(e[0] - first, e[1] - first);
    const auto it = std::lower_bound(per_tet_edge.begin(), per_tet_edge.end(), key,
                                     [](const Entry& a, std::uint64_t k) { return a.key < k; });
    out.push_back(it != per_tet_edge.end() && it->key == key ? it->value : weakest);
  }
  return out;
}

}  // namespace viscera::sim
