#pragma once
/// Bicubic spline surfaces through a grid of points (seed 002 §3.1; seed 001 §3.3 spline-surface
/// modelling): piecewise Bézier patches whose control points come from the Catmull-Rom method
/// applied along the rows and then along the columns, with knots from the averaged chord
/// lengths of the rows and of the columns, so the surface interpolates every grid point and is
/// tangent-continuous across patch borders. Either direction may be closed (a tube's periphery).
/// Positions in m.

#include <array>
#include <vector>

#include "core/curves/catmull_rom.h"
#include "core/math_types.h"
#include "core/mesh/surface_mesh.h"

namespace viscera::core {

/// A tensor-product piecewise bicubic Bézier surface through a rows × cols grid. Grid point
/// (row r, column c) is points[r·cols + c]; u runs along a row (over columns), v across rows.
class BicubicSurface {
 public:
  /// Needs ≥ 2 columns (≥ 3 when closed_u) and ≥ 2 rows (≥ 3 when closed_v), finite points,
  /// and a positive averaged knot gap between every pair of neighbouring columns and rows.
  /// Throws UsageError naming the grid line otherwise.
  BicubicSurface(std::vector<Vec3> points, int rows, int cols, bool closed_u, bool closed_v,
                 KnotSpacing spacing = KnotSpacing::ChordLength);

  int rows() const { return rows_; }
  int cols() const { return cols_; }
  bool closed_u() const { return closed_u_; }
  bool closed_v() const { return closed_v_; }
  int patches_u() const { return static_cast<int>(gaps_u_.size()); }
  int patches_v() const { return static_cast<int>(gaps_v_.size()); }
  const std::vector<Vec3>& grid() const { return points_; }
  const std::vector<double>& knot_gaps_u() const { return gaps_u_; }
  const std::vector<double>& knot_gaps_v() const { return gaps_v_; }

  /// Point at patch coordinates u ∈ [0, patches_u()], v ∈ [0, patches_v()]; grid point (r, c)
  /// sits at (u, v) = (c, r). Coordinates outside are clamped, or wrapped in a closed direction.
  Vec3 point(double u, double v) const;
  /// Partial derivatives with respect to the knot parameters (m per unit knot).
  Vec3 derivative_u(double u, double v) const;
  Vec3 derivative_v(double u, double v) const;
  /// Unit normal along S_u × S_v; at a degenerate point (a pole) the cross product of the
  /// nearest non-vanishing derivatives, or +z when all vanish.
  Vec3 normal(double u, double v) const;

  /// The 16 Bézier control points of patch (pu, pv), index a + 4b for the a-th along u and the
  /// b-th along v.
  std::array<Vec3, 16> patch(int pu, int pv) const;

 private:
  struct Local {
    int pu, pv;
    double a, b;
  };
  Local locate(double u, double v) const;
  Vec3 evaluate(const Local& at, int du, int dv) const;

  std::vector<Vec3> points_;
  int rows_, cols_;
  bool closed_u_, closed_v_;
  std::vector<double> gaps_u_, gaps_v_;
  std::vector<Vec3> net_;  ///< (3·patches_v + 1) rows × (3·patches_u + 1) columns
  int net_cols_ = 0;
};

/// How finely a surface is sampled: steps per patch in each direction.
struct SurfaceTessellation {
  int u_steps_per_patch = 8;
  int v_steps_per_patch = 8;
};

/// The samples of a surface on a regular grid in patch coordinates. A closed direction shares
/// its seam: it has patches·steps samples, an open one patches·steps + 1.
struct SurfaceSamples {
  int columns = 0;              ///< samples along u
  int rows = 0;                 ///< samples along v
  std::vector<Vec3> positions;  ///< rows × columns, row-major
  std::vector<Vec3> normals;    ///< unit, along S_u × S_v
  std::vector<Vec2> uvs;        ///< (u / patches_u, v / patches_v) ∈ [0, 1]²
  int index(int row, int column) const { return row * columns + column; }
};

/// Samples `surface`. Throws UsageError for steps < 1.
SurfaceSamples sample_surface(const BicubicSurface& surface,
                              const SurfaceTessellation& tessellation);

/// Triangles over the sample grid (two per cell, wrapping in closed directions), counter-
/// clockwise around S_u × S_v. Vertices, normals and UVs are the samples; in a closed direction
/// the seam vertices are shared, so texture coordinates wrap there (a texture atlas cuts its
/// own seams). A surface closed in both directions is a watertight torus.
SurfaceMesh tessellate(const BicubicSurface& surface, const SurfaceTessellation& tessellation);

/// The same triangulation for given samples (used by primitives that offset the samples).
std::vector<Triangle> sample_grid_triangles(int rows, int columns, bool closed_u, bool closed_v);

}  // namespace viscera::core
