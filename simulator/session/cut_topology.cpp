#include "simulator/session/cut_topology.h"

#include <algorithm>
#include <array>

namespace viscera::sim {

namespace {

/// The cut's node sources as the core's per-node origins (at most four: an unchanged or copied
/// node has one, a node on a cut edge two, a relaxed node the four corners of its old tet).
std::vector<NodeOrigin> node_origins(const cutting::TopologyChange& change) {
  std::vector<NodeOrigin> origins(change.mesh.nodes.size());
  for (std::size_t i = 0; i < origins.size(); ++i) {
    auto [begin, end] = change.sources(static_cast<int>(i));
    // At most four by the cut's rules; anything longer keeps its four heaviest, renormalised.
    std::array<cutting::NodeSource, 4> kept{};
    std::size_t count = 0;
    for (const cutting::NodeSource* s = begin; s != end; ++s) {
      if (count < kept.size()) {
        kept[count++] = *s;
        continue;
      }
      auto lightest = std::min_element(kept.begin(), kept.end(), [](const auto& a, const auto& b) {
        return a.weight < b.weight;
      });
      if (s->weight > lightest->weight) *lightest = *s;
    }
    double total = 0.0;
    for (std::size_t k = 0; k < count; ++k)
      total += kept[k].weight;
    for (std::size_t k = 0; k < count; ++k) {
      origins[i].node[k] = kept[k].old_node;
      origins[i].weight[k] = total > 0.0 ? kept[k].weight / total : 0.0;
    }
  }
  return origins;
}

}  // namespace

BodyTopology topology_of_cut(const cutting::TopologyChange& change) {
  BodyTopology topology;
  topology.rest_mesh = change.mesh;
  topology.positions = change.current;
  topology.origin = node_origins(change);
  topology.tet_parent = change.tet_parent;
  return topology;
}

}  // namespace viscera::sim
