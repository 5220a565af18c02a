#pragma once
/// Node separation and the new surface of the hybrid cut (seed 000 §5.1: "three schemes where
/// one, two, or three existing nodes are separated"). Internal to simulator/cutting.

#include <cstdint>
#include <vector>

#include "simulator/cutting/topology_change.h"

namespace viscera::sim::cutting {

/// The body between decomposition and separation, all arrays indexed by node or tet.
struct CutWork {
  std::vector<core::Vec3> rest, current;
  std::vector<core::Tetrahedron> tets;
  std::vector<int> parent;                      ///< per tet: the old tet
  std::vector<std::vector<NodeSource>> origin;  ///< per node; empty = itself
  std::vector<std::uint8_t> on_cut;             ///< per node
  std::vector<int> star_offset, star_tets;      ///< node → tets (CSR), conforming mesh
};

/// Fills w.star_offset / w.star_tets for the current tets.
void build_stars(CutWork& w);

struct SeparationResult {
  std::vector<int> affected;                  ///< sorted tets around nodes on the cut
  std::vector<core::Tetrahedron> conforming;  ///< the affected tets before separation
  /// Per affected tet and face (4 · index in affected + face, the face opposite that corner):
  /// the slot of the face across it before separation, for faces with a node on the cut;
  /// −1 for the others and for faces on the surface.
  std::vector<int> neighbour;
  std::size_t duplicated = 0;
};

/// Duplicates every node with on_cut set once per group of its tets connected through faces
/// that are not cut faces. A face is a cut face when its three nodes are on the cut and the
/// tets on its two sides lie on opposite sides (tet_side −1 / +1; 0 = undecided, never cut).
SeparationResult separate_cut_nodes(CutWork& w, const std::vector<std::int8_t>& tet_side);

/// For faces with a node on the cut (on_cut, per node) of positively oriented tets: the slot
/// (4 · tet + face) of the same face in another tet, or −1. Faces are matched by their nodes
/// after a counting sort on their lowest node.
std::vector<int> face_neighbours(const std::vector<core::Tetrahedron>& tets,
                                 const std::vector<std::uint8_t>& on_cut);

/// The surface faces after separation: the old ones that no affected tet touches, then the
/// boundary faces of the affected tets. cut_faces receives the indices of faces on the cut and
/// cut_face_tets the tet each of them bounds.
std::vector<core::Triangle> rebuild_surface(const std::vector<core::Triangle>& old_surface,
                                            const std::vector<core::Tetrahedron>& old_tets,
                                            const CutWork& w, const SeparationResult& separation,
                                            std::vector<int>& cut_faces,
                                            std::vector<int>& cut_face_tets);

}  // namespace viscera::sim::cutting
