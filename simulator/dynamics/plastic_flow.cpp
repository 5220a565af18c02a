#include "simulator/dynamics/plastic_flow.h"

#include <algorithm>
#include <cmath>

namespace viscera::sim {

int apply_plastic_flow(std::span<const Vec3> x, std::span<const std::array<int, 2>> edges,
                       std::span<double> rest_length, std::span<const double> yield_strain,
                       std::span<const double> longest) {
  int moved = 0;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const double yield = yield_strain[e];
    if (!(yield > 0.0)) continue;
    const double squared =
        (x[static_cast<std::size_t>(edges[e][1])] - x[static_cast<std::size_t>(edges[e][0])])
            .squaredNorm();
    double& rest = rest_length[e];
    if (certainly_within(squared, (1.0 + yield) * rest)) continue;
    const double length = std::sqrt(squared);
    if (!(length > (1.0 + yield) * rest)) continue;
    const double flowed = std::min(length / (1.0 + yield), longest[e]);
    if (flowed > rest) {
      rest = flowed;
      ++moved;
    }
  }
  return moved;
}

PlasticFlow::PlasticFlow(BodyEdges edges, const SimulationState& state) : edges_(edges) {
  capture(state);
}

void PlasticFlow::capture(const SimulationState& state) {
  const int first = state.body(edges_.model().body).first;
  yield_ = edges_.material_limit(&core::Material::plastic_yield, first);
  const std::vector<double> tearing =
      edges_.material_limit(&core::Material::tearing_threshold, first);
  const auto rest = edges_.rest_lengths();
  longest_.resize(rest.size());
  for (std::size_t e = 0; e < rest.size(); ++e)
    longest_[e] = rest[e] * (1.0 + std::max(0.0, tearing[e]));
}

void PlasticFlow::after_step(const SimulationState& state) {
  flow_events_ +=
      apply_plastic_flow(state.positions, edges_.edges(), edges_.rest_lengths(), yield_, longest_);
}

void PlasticFlow::topology_changed(const SimulationState& state, int body) {
  if (body == edges_.model().body) capture(state);  // global indices live in the edge term
}

}  // namespace viscera::sim
