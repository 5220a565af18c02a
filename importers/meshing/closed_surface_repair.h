#pragma once
/// The checks every surface made from a label map passes before it is used: watertight (a closed
/// 2-manifold), outward oriented and free of self-intersections (CGAL Polygon_mesh_processing,
/// exact predicates). Defects that can be repaired locally are repaired; the rest are refused.
///
/// Self-intersections are refused, never repaired: CGAL 5.5's
/// PMP::experimental::remove_self_intersections() has no time bound and no cancellation point
/// (on CGAL's liver at label 255 it ran 20 s of CPU before reaching the Kd_tree layout clash of
/// issue 20, fixed in importers/CMakeLists.txt). label_surface() makes such a surface again with
/// a larger decimation budget instead, which is bounded and cancellable.

#include <cstddef>
#include <string>

#include "core/mesh/surface_mesh.h"

namespace viscera::importers {

/// What repair_closed_surface() changed.
struct SurfaceRepairReport {
  std::size_t merged_vertices = 0;  ///< duplicate points joined, degenerate faces dropped
  std::size_t split_non_manifold_vertices = 0;  ///< pinched vertices duplicated
  std::size_t filled_holes = 0;                 ///< border cycles closed by triangulation
  bool reoriented = false;                      ///< at least one component was turned inside out

  bool any() const {
    return merged_vertices || split_non_manifold_vertices || filled_holes || reoriented;
  }
};

/// Makes `mesh` a closed, outward-oriented surface without self-intersections: joins duplicate
/// points, drops degenerate faces, splits non-manifold vertices, fills holes and orients every
/// component to bound a volume (PMP::orient_to_bound_a_volume). Normals and attributes are
/// dropped; vertex order may change. Throws core::InputError naming `what` for non-finite
/// coordinates, core::ValidationError naming `what` and the reason when a defect remains (a
/// self-intersection: "the surface intersects itself (N pairs of triangles cross)").
SurfaceRepairReport repair_closed_surface(core::SurfaceMesh& mesh, const std::string& what);

/// Throws core::ValidationError naming `what` unless `mesh` is closed, manifold, outward
/// oriented and free of self-intersections.
void check_closed_surface(const core::SurfaceMesh& mesh, const std::string& what);

}  // namespace viscera::importers
