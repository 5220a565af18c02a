#include "simulator/dynamics/node_reference.h"

#include <limits>

namespace viscera::sim {

NodeReference reference_node(const SimulationState& state, int body, int node) {
  return {body, node,
          state.rest_positions[static_cast<std::size_t>(state.body(body).first + node)]};
}

void refind_nodes(const SimulationState& state, int body, std::vector<NodeReference>& nodes,
                  double tolerance) {
  const auto rest = state.range(state.rest_positions, body);
  std::vector<NodeReference> kept;
  kept.reserve(nodes.size());
  for (NodeReference r : nodes) {
    if (r.body != body) {
      kept.push_back(r);
      continue;
    }
    double best = std::numeric_limits<double>::infinity();
    int found = -1;
    for (std::size_t n = 0; n < rest.size(); ++n) {
      const double d = (rest[n] - r.rest).squaredNorm();
      if (d < best) best = d, found = static_cast<int>(n);
    }
    if (found < 0 || best > tolerance * tolerance) continue;
    r.node = found;
    kept.push_back(r);
  }
  nodes = std::move(kept);
}

}  // namespace viscera::sim
