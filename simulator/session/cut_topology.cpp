#include "simulator/session/cut_topology.h"

#include <algorithm>
#include <array>

#include "simulator/cutting/fragments.h"

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

/// Nodes of `held` (before the cut, by old index) that the cut passed through and whose piece
/// holds on by no other node: the cut went through that piece's hold.
std::vector<std::uint8_t> cut_loose(const cutting::TopologyChange& change,
                                    std::span<const std::uint8_t> held) {
  const std::size_t n = change.mesh.nodes.size();
  std::vector<std::uint8_t> released(n, 0);
  if (held.empty()) return released;
  const auto holds = [&](std::size_t i) { return i < held.size() && held[i] != 0; };
  const auto on_cut = [&](std::size_t i) { return i < change.on_cut.size() && change.on_cut[i]; };
  std::vector<std::uint8_t> anchored(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    anchored[i] = holds(i) && !on_cut(i);
  for (const cutting::Fragment& piece : cutting::body_fragments(change.mesh, anchored)) {
    if (piece.anchored) continue;
    for (const int node : piece.nodes) {
      const auto i = static_cast<std::size_t>(node);
      released[i] = holds(i) && on_cut(i);
    }
  }
  return released;
}

}  // namespace

BodyTopology topology_of_cut(const cutting::TopologyChange& change,
                             std::span<const std::uint8_t> held) {
  BodyTopology topology;
  topology.rest_mesh = change.mesh;
  topology.positions = change.current;
  topology.origin = node_origins(change);
  topology.tet_parent = change.tet_parent;
  topology.released = cut_loose(change, held);
  return topology;
}

}  // namespace viscera::sim
