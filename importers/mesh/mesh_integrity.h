#pragma once
/// Checks that a mesh read from a file is fit for the studio and the simulator: the defects that
/// no later step can repair silently are refused with the file and the element named.

#include <string>
#include <vector>

#include "core/mesh/surface_mesh.h"
#include "core/mesh/tet_mesh.h"

namespace viscera::importers {

/// For every vertex, the index of the first vertex at exactly the same position (itself if none
/// comes before it). Exact comparison, no tolerance: only identical coordinates are one point.
std::vector<int> first_copy_by_position(const std::vector<core::Vec3>& vertices);

/// Joins vertices whose position, normal and UV are all exactly equal and drops unused ones:
/// STL and assimp's OBJ reader store every triangle corner separately. (assimp's own joining
/// works within a tolerance of the bounding box and merges distinct corners of small meshes.)
void join_identical_vertices(core::SurfaceMesh& mesh);

/// Checks a surface, its vertices joined by position first (so that copies made for UV seams or
/// per-face normals count as one): finite coordinates and attributes, no triangle with two
/// corners at the same position or with collinear corners, no edge shared by more than two
/// triangles, no vertex whose triangles form several fans (non-manifold vertex), and no two
/// triangles that intersect other than at shared edges or corners
/// (CGAL::Polygon_mesh_processing::self_intersections, exact predicates). Open borders and
/// several components are allowed. Throws core::InputError naming `file`, the element and the
/// defect.
void check_surface_integrity(const core::SurfaceMesh& mesh, const std::string& file);

/// Checks a positively oriented tetrahedral mesh beyond core::check_tet_mesh (no triangle shared
/// by more than two tetrahedra) and returns its boundary faces, outward, in the order of
/// core::boundary_faces (by sorted corner indices) — by sorting instead of a tree, which makes
/// it several times faster on large meshes. Throws core::InputError naming `file` and a tet.
std::vector<core::Triangle> checked_boundary_faces(const core::TetMesh& mesh,
                                                   const std::string& file);

}  // namespace viscera::importers
