#include "simulator/dynamics/tissue_tearing.h"

#include <cmath>

namespace viscera::sim {

TissueTearing::TissueTearing(BodyEdges edges, const SimulationState& state) : edges_(edges) {
  capture(state);
}

void TissueTearing::capture(const SimulationState& state) {
  first_ = state.body(edges_.model().body).first;
  const auto rest = edges_.rest_lengths();
  original_.assign(rest.begin(), rest.end());
  threshold_ = edges_.material_limit(&core::Material::tearing_threshold, first_);
  torn_.assign(original_.size(), 0);
}

void TissueTearing::after_step(const SimulationState& state) {
  first_ = state.body(edges_.model().body).first;
  const auto edges = edges_.edges();
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (torn_[e] || !(threshold_[e] > 0.0) || !(original_[e] > 0.0)) continue;
    const double squared = (state.positions[static_cast<std::size_t>(edges[e][1])] -
                            state.positions[static_cast<std::size_t>(edges[e][0])])
                               .squaredNorm();
    if (certainly_within(squared, original_[e] * (1.0 + threshold_[e]))) continue;
    const double length = std::sqrt(squared);
    const double strain = length / original_[e] - 1.0;
    if (strain <= threshold_[e]) continue;
    torn_[e] = 1;
    tears_.push_back({state.time, edges_.model().name, edges[e][0] - first_, edges[e][1] - first_,
                      strain, threshold_[e]});
  }
}

void TissueTearing::topology_changed(const SimulationState& state, int body) {
  if (body == edges_.model().body) capture(state);  // the new rest mesh's edges start whole
}

}  // namespace viscera::sim
