#pragma once
/// A bounding-volume hierarchy over the triangles of a surface, for the headless camera: rays
/// from the endoscope (what the camera sees, first hit) and the nearest wall point (the tool's
/// distance to the wall, seed 000 Fig. 16). Built once per topology by median splits of the
/// triangle centroids along the longest axis; refit() follows a deforming surface in O(n).

#include <span>
#include <vector>

#include "core/math_types.h"

namespace viscera::sim {

/// The first triangle a ray meets.
struct RayHit {
  int triangle = -1;    ///< −1: the ray meets nothing
  double distance = 0;  ///< m along the (unit) ray direction
};

/// The nearest surface point to a query point.
struct NearestPoint {
  int triangle = -1;
  double distance = 0;  ///< m
  core::Vec3 point = core::Vec3::Zero();
};

/// BVH of axis-aligned boxes over a triangle surface.
class SurfaceBvh {
 public:
  SurfaceBvh() = default;
  /// Keeps the connectivity; builds the tree for `positions` (m). Triangles index `positions`.
  SurfaceBvh(std::vector<core::Triangle> triangles, std::span<const core::Vec3> positions);

  /// Recomputes every box for new positions of the same vertices (the tree shape is kept).
  void refit(std::span<const core::Vec3> positions);

  /// First hit of the ray origin + t·direction, 0 < t ≤ max_distance; `direction` is unit.
  RayHit cast(const core::Vec3& origin, const core::Vec3& direction, double max_distance) const;
  /// Nearest point of the surface to `point`, or triangle −1 for an empty surface.
  NearestPoint nearest(const core::Vec3& point) const;

  const std::vector<core::Triangle>& triangles() const { return triangles_; }
  const std::vector<core::Vec3>& positions() const { return positions_; }
  bool empty() const { return triangles_.empty(); }

 private:
  struct Node {
    core::Vec3 lo = core::Vec3::Zero(), hi = core::Vec3::Zero();
    int first = 0, count = 0;  ///< leaf: range in order_; inner: count 0
    int left = -1, right = -1;
  };
  int build(int first, int count, std::vector<core::Vec3>& centroids);
  void fit(int node);

  std::vector<core::Triangle> triangles_;
  std::vector<core::Vec3> positions_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

}  // namespace viscera::sim
