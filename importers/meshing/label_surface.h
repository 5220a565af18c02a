#pragma once
/// Label map → closed triangle surface of one label (issue 3 §3): discrete flying edges on the
/// label's voxels (VTK vtkDiscreteFlyingEdges3D, marching cubes on the binary label indicator at
/// level ½), windowed-sinc smoothing (Taubin, Zhang & Golub 1996; vtkWindowedSincPolyDataFilter),
/// quadric decimation to a triangle budget (Garland & Heckbert 1997 with Lindstrom–Turk volume
/// preservation; vtkQuadricDecimation), then the watertight/outward/self-intersection checks and
/// repairs of closed_surface_repair.h.

#include <cstddef>
#include <map>
#include <string>

#include "core/image/image_volume.h"
#include "core/mesh/surface_mesh.h"
#include "core/progress.h"
#include "importers/meshing/closed_surface_repair.h"

namespace viscera::importers {

/// Parameters of the label-surface pipeline.
struct LabelSurfaceOptions {
  int smoothing_iterations = 20;  ///< windowed-sinc iterations; 0 = no smoothing
  /// Pass band of the windowed-sinc filter in (0, 2): smaller smooths more (0.01 removes the
  /// voxel staircase and keeps features a few voxels wide, Slicer's "0.5" smoothing factor).
  double pass_band = 0.01;
  /// Triangle budget for quadric decimation; 0 or more than flying edges gives = no decimation.
  /// Doubled (LabelSurface::decimation_retries) while the decimated surface intersects itself;
  /// a smoothed surface that intersects itself undecimated gives way to the unsmoothed contour
  /// (LabelSurface::smoothing_dropped).
  std::size_t target_triangles = 0;
};

/// The surface of one label and what was done to it.
struct LabelSurface {
  int label = 0;           ///< the label (0: the union of all labels)
  core::SurfaceMesh mesh;  ///< in m, world frame of the map, outward, unit vertex normals
  std::size_t extracted_triangles = 0;  ///< triangles from flying edges, before decimation
  SurfaceRepairReport repair;
  /// Times the triangle budget was doubled because decimation left self-intersections that
  /// local repair could not remove.
  std::size_t decimation_retries = 0;
  /// The smoothed surface intersected itself even undecimated, so the unsmoothed contour is
  /// used.
  bool smoothing_dropped = false;
  /// Wall-clock seconds per step: "contour", "smoothing", "decimation", "repair".
  std::map<std::string, double> seconds;
};

/// The surface of the voxels whose label is `label` (every label other than 0 when `label` is
/// 0), in metres in the map's world frame (spacing, origin and direction applied). Each
/// connected component is a closed, outward-oriented 2-manifold free of self-intersections.
/// Throws core::InputError naming `what` for an empty map or a label without voxels,
/// core::ValidationError naming `what` when the surface cannot be repaired, CancelledError.
LabelSurface label_surface(const core::LabelMap& labels, int label,
                           const LabelSurfaceOptions& options, const std::string& what,
                           core::Progress& progress = core::Progress::none());

}  // namespace viscera::importers
