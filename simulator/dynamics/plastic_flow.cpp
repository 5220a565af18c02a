#include "simulator/dynamics/plastic_flow.h"

namespace viscera::sim {

int apply_plastic_flow(std::span<const Vec3> x, std::span<const std::array<int, 2>> edges,
                       std::span<double> rest_length, std::span<const double> yield_strain) {
  int moved = 0;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const double yield = yield_strain[e];
    if (!(yield > 0.0)) continue;
    const double length =
        (x[static_cast<std::size_t>(edges[e][1])] - x[static_cast<std::size_t>(edges[e][0])])
            .norm();
    double& rest = rest_length[e];
    if (length > (1.0 + yield) * rest) {
      rest = length / (1.0 + yield);
      ++moved;
    } else if (yield < 1.0 && length > 0.0 && length < (1.0 - yield) * rest) {
      rest = length / (1.0 - yield);
      ++moved;
    }
  }
  return moved;
}

PlasticFlow::PlasticFlow(BodyEdges edges, const SimulationState& state) : edges_(edges) {
  yield_ =
      edges_.material_limit(&core::Material::plastic_yield, state.body(edges_.model().body).first);
}

void PlasticFlow::after_step(const SimulationState& state) {
  flow_events_ +=
      apply_plastic_flow(state.positions, edges_.edges(), edges_.rest_lengths(), yield_);
}

void PlasticFlow::topology_changed(const SimulationState& state, int body) {
  if (body != edges_.model().body) return;  // global indices live in the edge term
  yield_ = edges_.material_limit(&core::Material::plastic_yield, state.body(body).first);
}

}  // namespace viscera::sim
