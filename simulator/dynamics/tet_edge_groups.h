#pragma once
/// The edges of a tet mesh with the tets around each: what the distance terms (seed 000 §3)
/// and the KisMo springs (seed 001 §3.2) sum over when they are built, and rebuilt after every
/// cut. Edges come in sorted order and each edge's tets in tet order, so sums over them run
/// the same way on every machine.

#include <array>
#include <vector>

#include "core/mesh/tet_mesh.h"

namespace viscera::sim {

struct TetEdgeGroups {
  std::vector<std::array<int, 2>> edges;  ///< (lower node, upper node), sorted
  std::vector<int> first;                 ///< per edge, then the end: ranges in `tets`
  std::vector<int> tets;                  ///< the tets around each edge, ascending
};

/// Groups the six edges of every tet (node ids in [0, node_count)): a radix sort of the tet
/// edges, two stable counting passes (upper node, then lower node). Linear in the tets and
/// nodes, where a std::map of the edges costs a tree insertion per tet edge.
TetEdgeGroups tet_edge_groups(const std::vector<core::Tetrahedron>& tets, int node_count);

}  // namespace viscera::sim
