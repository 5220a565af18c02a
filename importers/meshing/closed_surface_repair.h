#pragma once
/// The checks every surface made from a label map passes before it is used: watertight (a closed
/// 2-manifold), outward oriented and free of self-intersections (CGAL Polygon_mesh_processing,
/// exact predicates). Defects that can be repaired locally are repaired; the rest are refused.

#include <cstddef>
#include <string>

#include "core/mesh/surface_mesh.h"

namespace viscera::importers {

/// What repair_closed_surface() changed.
struct SurfaceRepairReport {
  std::size_t merged_vertices = 0;  ///< duplicate points joined, degenerate faces dropped
  std::size_t split_non_manifold_vertices = 0;  ///< pinched vertices duplicated
  std::size_t filled_holes = 0;                 ///< border cycles closed by triangulation
  bool self_intersections_removed = false;      ///< PMP's local self-intersection repair ran
  bool reoriented = false;                      ///< at least one component was turned inside out

  bool any() const {
    return merged_vertices || split_non_manifold_vertices || filled_holes ||
           self_intersections_removed || reoriented;
  }
};

/// Makes `mesh` a closed, outward-oriented surface without self-intersections: joins duplicate
/// points, drops degenerate faces, splits non-manifold vertices, fills holes, removes
/// self-intersections locally (PMP::experimental::remove_self_intersections) and orients every
/// component to bound a volume (PMP::orient_to_bound_a_volume). Normals and attributes are
/// dropped; vertex order may change. Throws core::InputError naming `what` for non-finite
/// coordinates, core::ValidationError naming `what` and the reason when a defect remains.
SurfaceRepairReport repair_closed_surface(core::SurfaceMesh& mesh, const std::string& what);

/// Throws core::ValidationError naming `what` unless `mesh` is closed, manifold, outward
/// oriented and free of self-intersections.
void check_closed_surface(const core::SurfaceMesh& mesh, const std::string& what);

}  // namespace viscera::importers
