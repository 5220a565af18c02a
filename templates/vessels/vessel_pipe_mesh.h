#pragma once
/// Closed pipe surfaces of vessel trees with smooth bifurcations: the tree is the zero set of
/// the union of its segments' capsule distance fields, blended with a polynomial smooth minimum
/// (Quilez 2013) only where a parent meets its children, so bifurcations get fillets while
/// straight runs stay exact tubes. The field is polygonised on a sparse grid around the tree by
/// marching tetrahedra on the Freudenthal split of each cube, which needs no case tables and
/// yields a watertight, consistently oriented surface.

#include <cstddef>

#include "core/mesh/surface_mesh.h"
#include "core/progress.h"
#include "core/scenario/scenario_parts.h"

namespace viscera::templates {

/// Resolution and blending of the pipe surface.
struct PipeMeshOptions {
  double voxel_size =
      0.0;  ///< m; 0 = the larger of (thinnest meshed radius / 1.5) and (tree extent / 400)
  double min_radius = 0.0;  ///< m; thinner segments are left out; 0 = 0.75 · voxel size
  double blend = 0.6;       ///< fillet width at bifurcations as a fraction of the thinner radius
  std::size_t max_cells = 6'000'000;  ///< refuse grids with more active cells than this
};

/// The pipe surface of `tree` in m, with outward normals. Throws core::UsageError when no
/// segment is thick enough for the voxel size or the grid would exceed max_cells; CancelledError
/// through `progress`.
core::SurfaceMesh vessel_pipe_mesh(const core::VesselTree& tree,
                                   const PipeMeshOptions& options = {},
                                   core::Progress& progress = core::Progress::none());

}  // namespace viscera::templates
