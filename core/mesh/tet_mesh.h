#pragma once
/// Tetrahedral meshes: the simulation body of a scene object (DESIGN.md §3).

#include <cstdint>
#include <string>
#include <vector>

#include "core/math_types.h"

namespace viscera::core {

/// Nodes in m, tetrahedra with positive signed volume, outward boundary faces, lumped node
/// masses in kg and fixed-node flags (nodes held at their rest position by the simulator).
struct TetMesh {
  std::vector<Vec3> nodes;
  std::vector<Tetrahedron> tets;
  std::vector<Triangle> surface_faces;  ///< boundary triangles, outward
  std::vector<double> node_mass;        ///< kg per node, or empty before masses are assigned
  std::vector<std::uint8_t> fixed;      ///< 1 for fixed nodes; empty means none fixed
  std::vector<int> tet_labels;          ///< tissue label per tet, or empty

  bool operator==(const TetMesh&) const = default;
};

/// Signed volume in m³ of tet (a,b,c,d): (b-a)·((c-a)×(d-a))/6.
double signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
/// Signed volume of tet `t` of `mesh`.
double signed_volume(const TetMesh& mesh, int t);
/// Sum of signed tet volumes in m³.
double total_volume(const TetMesh& mesh);
/// Boundary faces (those used by exactly one tet), oriented outward; deterministic order.
std::vector<Triangle> boundary_faces(const std::vector<Tetrahedron>& tets);
/// Lumped masses: each tet gives a quarter of density·volume to each of its nodes.
/// density in kg/m³.
std::vector<double> lumped_node_masses(const TetMesh& mesh, double density);
/// Reorders nodes of tets with negative volume so that every tet is positively oriented.
void orient_tets_positively(TetMesh& mesh);
/// Throws InputError naming `what` and the element on bad indices, non-finite nodes,
/// array length mismatches or degenerate/inverted tets.
void check_tet_mesh(const TetMesh& mesh, const std::string& what);

}  // namespace viscera::core
