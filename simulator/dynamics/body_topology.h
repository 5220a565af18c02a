#pragma once
/// A new topology of one body, as the cutting module produces it and
/// World::topology_changed consumes it.

#include <array>
#include <cstdint>
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

}  // namespace viscera::sim
