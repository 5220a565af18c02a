#pragma once
/// KisMo's "flat" object type (seed 001 §3.3): a sheet shaped by a grid of control points,
/// interpolated by a bicubic spline surface (Catmull-Rom Bézier patches, seed 002 §3.1). By
/// default it is tessellated as a closed slab of the given thickness — watertight, outward, ready
/// for tetrahedral meshing; as an open sheet on request. Positions in m.

#include <vector>

#include "core/mesh/surface_mesh.h"
#include "core/surfaces/bicubic_surface.h"

namespace viscera::core {

/// A flat: a rows × cols grid of control points (row-major) and how to tessellate it.
struct FlatPrimitive {
  int rows = 4;
  int cols = 4;
  std::vector<Vec3> control_points;  ///< m, rows × cols, row-major; u along a row
  double thickness = 0.003;          ///< m, of the closed slab
  bool open = false;                 ///< tessellate as an open sheet instead of a slab
  int steps_per_patch = 6;           ///< tessellation steps per spline patch in u and in v

  bool operator==(const FlatPrimitive&) const = default;
};

/// A planar grid from `origin` spanning `u_edge` × `v_edge` (m), its normal u_edge × v_edge.
/// Throws UsageError for fewer than 2 × 2 points, parallel edges or a negative thickness.
FlatPrimitive make_flat(const Vec3& origin, const Vec3& u_edge, const Vec3& v_edge, int rows,
                        int cols, double thickness = 0.003);

/// Throws UsageError naming `what` when the fields disagree.
void check_flat(const FlatPrimitive& flat, const std::string& what);

/// The spline surface through the control grid (open in both directions, chord-length knots).
BicubicSurface flat_surface(const FlatPrimitive& flat);

/// The tessellation: an open sheet (normals along S_u × S_v, UVs in [0,1]²) or a closed slab
/// whose faces lie ±thickness/2 along the surface normal, joined by a rim; the slab is
/// watertight and outward. Offsetting folds where the sheet bends tighter than thickness/2.
SurfaceMesh tessellate_flat(const FlatPrimitive& flat);

}  // namespace viscera::core
