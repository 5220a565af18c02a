#pragma once
/// A uniform grid over the triangles of a cut surface, for the two queries of the hybrid cut:
/// where a tet edge crosses the surface, and how far a node lies from it (node snapping).

#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "simulator/cutting/cut_surface.h"

namespace viscera::sim::cutting {

/// Where a segment a→b crosses the cut surface.
struct SegmentCrossing {
  double t = 0.0;  ///< parameter along a→b, in [0, 1]
  /// +1 when the segment goes from the surface's "−" side to its "+" side, −1 otherwise.
  int direction = 0;
};

/// The point of the surface nearest to a query point.
struct NearestPoint {
  double distance = 0.0;         ///< m
  double signed_distance = 0.0;  ///< m, positive on the "+" side (the triangle's normal)
  core::Vec3 point = core::Vec3::Zero();
  core::Vec3 normal = core::Vec3::Zero();  ///< unit normal of the nearest triangle
};

class CutSurfaceIndex {
 public:
  /// cell_size in m (> 0); the surface is copied.
  CutSurfaceIndex(CutSurface surface, double cell_size);

  const CutSurface& surface() const { return surface_; }
  core::BoundingBox bounds() const { return bounds_; }

  /// The crossing of segment a→b with the surface when it crosses it an odd number of times
  /// (coincident hits on shared triangle edges count once): the median hit. nullopt otherwise.
  std::optional<SegmentCrossing> crossing(const core::Vec3& a, const core::Vec3& b) const;

  /// The nearest surface point within `radius` m of p, or nullopt.
  std::optional<NearestPoint> nearest(const core::Vec3& p, double radius) const;

  /// The grid cell of point p (m), clamped to the grid; points beyond it land in its empty
  /// margin cells, so a box of cells found from clamped corners never misses a triangle.
  std::array<int, 3> cell_of(const core::Vec3& p) const;

  /// Six bits, one per face of the surface's box (grown by 1e-9 of a cell), set when p (m)
  /// lies beyond it (Cohen–Sutherland). Points whose codes share a bit lie beyond one face
  /// together: no segment or box between them reaches the surface.
  std::uint8_t outcode(const core::Vec3& p) const {
    std::uint8_t code = 0;
    for (int d = 0; d < 3; ++d) {
      code |= static_cast<std::uint8_t>((p[d] < outer_.min[d] ? 1 : 0) << (2 * d));
      code |= static_cast<std::uint8_t>((p[d] > outer_.max[d] ? 1 : 0) << (2 * d + 1));
    }
    return code;
  }

  /// True when a grid cell in the box of cells [lo, hi] (from cell_of) holds a triangle.
  bool cells_hold_triangle(const std::array<int, 3>& lo, const std::array<int, 3>& hi) const;

  /// True when a triangle of the cells [lo, hi] may meet `box` (m): their boxes overlap and the
  /// triangle's plane passes through the box. False means no segment inside the box crosses
  /// the surface (the box grows by 1e-9 of a cell for the crossing test's tolerance).
  bool triangle_may_meet(const std::array<int, 3>& lo, const std::array<int, 3>& hi,
                         const core::BoundingBox& box) const;

 private:
  std::int64_t key(int i, int j, int k) const;
  template <typename Visit>
  void for_triangles_in(const core::BoundingBox& box, Visit&& visit) const;

  CutSurface surface_;
  std::vector<core::Vec3> normals_;
  std::vector<core::BoundingBox> boxes_;  ///< per triangle
  double cell_ = 0.0;
  double inverse_cell_ = 0.0;  ///< 1 / cell_: a cell lookup multiplies
  core::BoundingBox bounds_;
  core::BoundingBox outer_;  ///< bounds_ grown by 1e-9 of a cell, for outcode
  core::Vec3 origin_ = core::Vec3::Zero();
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<std::pair<std::int64_t, int>> cells_;  ///< sorted (cell key, triangle)
  std::vector<int> first_;                    ///< per cell + 1: start of its entries in cells_
  mutable std::vector<std::uint32_t> stamp_;  ///< per triangle, de-duplicates visits
  mutable std::uint32_t query_ = 0;
};

}  // namespace viscera::sim::cutting
