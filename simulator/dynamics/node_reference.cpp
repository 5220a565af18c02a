#include "simulator/dynamics/node_reference.h"

#include <algorithm>
#include <limits>

namespace viscera::sim {

NodeReference reference_node(const SimulationState& state, int body, int node) {
  const auto g = static_cast<std::size_t>(state.body(body).first + node);
  return {body, node, state.rest_positions[g], state.positions[g]};
}

void note_positions(const SimulationState& state, std::span<NodeReference> nodes) {
  for (NodeReference& r : nodes)
    r.seen = state.positions[static_cast<std::size_t>(r.global(state))];
}

std::vector<std::size_t> refind_nodes(const SimulationState& state, int body,
                                      std::vector<NodeReference>& nodes, double tolerance) {
  constexpr double kSameRest = 1e-9;  // m: copies of one node share their rest position
  const auto rest = state.range(state.rest_positions, body);
  const auto current = state.range(state.positions, body);
  std::vector<NodeReference> kept;
  std::vector<std::size_t> kept_from;
  kept.reserve(nodes.size());
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    NodeReference r = nodes[k];
    if (r.body != body) {
      kept.push_back(r);
      kept_from.push_back(k);
      continue;
    }
    double nearest_rest = std::numeric_limits<double>::infinity();
    for (std::size_t n = 0; n < rest.size(); ++n)
      nearest_rest = std::min(nearest_rest, (rest[n] - r.rest).norm());
    if (!(nearest_rest <= tolerance)) continue;
    double nearest_seen = std::numeric_limits<double>::infinity();
    int found = -1;
    for (std::size_t n = 0; n < rest.size(); ++n) {
      if ((rest[n] - r.rest).norm() > nearest_rest + kSameRest) continue;
      const double d = (current[n] - r.seen).squaredNorm();
      if (d < nearest_seen) nearest_seen = d, found = static_cast<int>(n);
    }
    r.node = found;
    kept.push_back(r);
    kept_from.push_back(k);
  }
  nodes = std::move(kept);
  return kept_from;
}

}  // namespace viscera::sim
