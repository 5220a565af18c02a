#pragma once
/// Fragments of a body after a cut: its connected components (tets sharing a node), their
/// volume and whether they kept an attachment. A fragment without any anchored node is a chip
/// that the session turns into a free body (seed 000 §5, Fig. 6–7: "Excised tissue moved
/// against fundus"), or into debris when its volume is below the caller's bound.

#include <cstdint>
#include <vector>

#include "core/mesh/tet_mesh.h"

namespace viscera::sim::cutting {

struct Fragment {
  std::vector<int> tets;     ///< ascending
  std::vector<int> nodes;    ///< ascending
  double rest_volume = 0.0;  ///< m³
  bool anchored = false;     ///< holds a node flagged in `anchored`
};

/// Connected components of `mesh` through shared nodes, ordered by their lowest tet.
/// anchored: per node, 1 for nodes that hold the body in place (fixed nodes, attachments to
/// another body); empty means mesh.fixed. Throws InputError when `anchored` has the wrong
/// length or a tet names a node that does not exist.
std::vector<Fragment> body_fragments(const core::TetMesh& mesh,
                                     const std::vector<std::uint8_t>& anchored = {});

/// The fragments that lost every anchor (chips), in the order of body_fragments.
std::vector<Fragment> excised_chips(const core::TetMesh& mesh,
                                    const std::vector<std::uint8_t>& anchored = {});

/// The sub-mesh of one fragment: its nodes renumbered in ascending order, its tets, surface
/// faces, masses, fixed flags and labels. node_map receives the old index of every new node.
core::TetMesh fragment_mesh(const core::TetMesh& mesh, const Fragment& fragment,
                            std::vector<int>* node_map = nullptr);

}  // namespace viscera::sim::cutting
