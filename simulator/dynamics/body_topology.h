#pragma once
/// A new topology of one body, as the cutting module produces it and
/// World::topology_changed consumes it.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/mesh/tet_mesh.h"

namespace viscera::sim {

/// How a new node's per-node data derive from old nodes: Σ weight[k] · old[node[k]] over the
/// entries with node ≥ 0 (−1 unused).
struct NodeOrigin {
  std::array<int, 4> node{-1, -1, -1, -1};
  std::array<double, 4> weight{};
};

struct BodyTopology {
  core::TetMesh rest_mesh;  ///< new tets, rest nodes (+ surface faces, labels, masses, fixed)
  std::vector<core::Vec3> positions;  ///< current positions of the new nodes, m
  std::vector<NodeOrigin> origin;     ///< per new node: how to carry per-node arrays
  std::vector<int> tet_parent;        ///< per new tet: the old tet it came from
  /// Per new node, 1 where the change cut the node loose from the other bodies (a loop drawn
  /// through a polyp's base nodes takes the polyp off the wall): its attachments and connection
  /// springs go. Empty: none.
  std::vector<std::uint8_t> released;
};

/// The topology a body already has: `mesh` at `positions`, every node and tet its own origin
/// (a change that changes nothing, which costs the world's rebuild what a new one does).
inline BodyTopology unchanged_topology(const core::TetMesh& mesh,
                                       std::span<const core::Vec3> positions) {
  BodyTopology topology;
  topology.rest_mesh = mesh;
  topology.positions.assign(positions.begin(), positions.end());
  topology.origin.resize(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    topology.origin[i].node[0] = static_cast<int>(i);
    topology.origin[i].weight[0] = 1.0;
  }
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    topology.tet_parent.push_back(static_cast<int>(t));
  return topology;
}

}  // namespace viscera::sim
