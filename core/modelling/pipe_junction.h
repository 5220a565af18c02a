#pragma once
/// Joining closed tubes into one surface with smooth junctions: CGAL's corefinement computes the
/// exact union; around each intersection curve a band of half-width `blend_width` is remeshed
/// isotropically and then faired (bi-Laplacian, tangent-continuous to the fixed surface around
/// it; Botsch and Kobbelt 2004, CGAL Polygon_mesh_processing::fair), which turns the sharp crease
/// into a fillet while the union stays watertight and outward.

#include <vector>

#include "core/mesh/surface_mesh.h"
#include "core/progress.h"

namespace viscera::core {

/// One tube to join and the fillet half-width in m at the curve where it meets the tubes before it.
struct JunctionTube {
  SurfaceMesh surface;       ///< closed, outward, not self-intersecting
  double blend_width = 0.0;  ///< m; 0 leaves that junction sharp
};

/// The union of tubes[0] with each later tube in order, with every junction smoothed.
/// `target_edge` (m) is the edge length of the remeshed bands. Throws InputError naming the
/// tube when one is open or self-intersecting, when the union is not manifold, or when fairing
/// fails; CancelledError through `progress`.
SurfaceMesh join_tubes(const std::vector<JunctionTube>& tubes, double target_edge,
                       Progress& progress = Progress::none());

}  // namespace viscera::core
