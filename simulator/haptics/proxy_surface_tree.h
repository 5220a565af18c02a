#pragma once
/// A bounding-box hierarchy over the triangles of a ProxySurface, so that the proxy's free-space
/// tests — does the path from the proxy to the tip enter the surface, how many triangles does a
/// ray from the tip cross — visit the triangles near the path instead of every triangle of every
/// body once per step (seed 000 §8.2's proxy, Ruspini et al. 1997; the tree is the usual
/// axis-aligned box hierarchy, Ericson 2005, Real-Time Collision Detection §6).
///
/// The tree's shape is built once per topology (median splits of the triangle centroids) and its
/// boxes are refitted when the positions move. Boxes are padded by kPadding so that no triangle
/// the exact test (segment_triangle_intersection) would accept is ever culled: the answers are
/// the same, bit for bit, as testing every triangle in order.

#include <span>
#include <vector>

#include "core/math_types.h"

namespace viscera::sim {

class ProxySurfaceTree {
 public:
  /// m added to every box on each side: far above the rounding of a hit point (1e-13 m on a
  /// 1 km parity ray), far below a triangle (0.1 mm and up).
  static constexpr double kPadding = 1e-9;

  ProxySurfaceTree() = default;
  /// Builds the tree over `faces` (indices into `positions`, m) at those positions.
  ProxySurfaceTree(std::span<const core::Triangle> faces, std::span<const core::Vec3> positions);

  /// Recomputes every box at new positions of the same vertices (the shape is kept).
  void refit(std::span<const core::Vec3> positions);
  /// The vertices have moved: the next query refits first (an explicit integrator's sub-steps
  /// move the surface many times between the queries that need the boxes).
  void mark_moved() { moved_ = true; }

  /// Of the triangles the segment p→q crosses from outside (against their outward normal), the
  /// one crossed first: its index and the segment parameter s ∈ [0, 1] of the crossing, the
  /// lowest index on a tie; −1 when none.
  struct Entry {
    int face = -1;
    double s = 0.0;
  };
  Entry first_entry(const core::Vec3& p, const core::Vec3& q, std::span<const core::Triangle> faces,
                    std::span<const core::Vec3> positions);

  /// How many triangles the segment p→q crosses, in either direction.
  int crossings(const core::Vec3& p, const core::Vec3& q, std::span<const core::Triangle> faces,
                std::span<const core::Vec3> positions);

  bool empty() const { return nodes_.empty(); }

 private:
  struct Node {
    core::Vec3 lo = core::Vec3::Zero(), hi = core::Vec3::Zero();
    int first = 0, count = 0;  ///< leaf: range in order_; inner: count 0, children first + 1
    int right = -1;            ///< inner: the right child (the left one follows the node)
  };
  int build(int first, int count, std::vector<core::Vec3>& centroids);
  /// Calls visit(face) for every face of every leaf whose box the segment p + t(q − p),
  /// t ∈ [0, reach()], meets; reach is re-read before each box (a shrinking search).
  template <typename Visit, typename Reach>
  void along_segment(const core::Vec3& p, const core::Vec3& q, Reach reach, Visit visit) const;

  std::vector<int> order_;
  std::vector<Node> nodes_;
  /// Per leaf (in node order), the distinct vertices of its faces: what a refit reads.
  std::vector<int> leaf_vertex_start_, leaf_vertices_;
  bool moved_ = false;
};

}  // namespace viscera::sim
