#include "simulator/camera/surface_bvh.h"

#include <algorithm>
#include <array>
#include <limits>

#include "simulator/collision/segment_box.h"
#include "simulator/haptics/haptic_proxy.h"

namespace viscera::sim {
namespace {

constexpr int kLeafSize = 4;

/// Möller–Trumbore ray/triangle intersection; returns t or +inf.
double intersect(const core::Vec3& o, const core::Vec3& d, const core::Vec3& a, const core::Vec3& b,
                 const core::Vec3& c) {
  const core::Vec3 e1 = b - a, e2 = c - a;
  const core::Vec3 p = d.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < 1e-20) return std::numeric_limits<double>::infinity();
  const double inv = 1.0 / det;
  const core::Vec3 s = o - a;
  const double u = s.dot(p) * inv;
  if (u < 0.0 || u > 1.0) return std::numeric_limits<double>::infinity();
  const core::Vec3 q = s.cross(e1);
  const double v = d.dot(q) * inv;
  if (v < 0.0 || u + v > 1.0) return std::numeric_limits<double>::infinity();
  const double t = e2.dot(q) * inv;
  return t > 0.0 ? t : std::numeric_limits<double>::infinity();
}

/// Slab test: entry distance of the ray into the box, or +inf when it misses within tmax.
double box_distance_squared(const core::Vec3& p, const core::Vec3& lo, const core::Vec3& hi) {
  return (p.cwiseMax(lo).cwiseMin(hi) - p).squaredNorm();
}

}  // namespace

SurfaceBvh::SurfaceBvh(std::vector<core::Triangle> triangles, std::span<const core::Vec3> positions)
    : triangles_(std::move(triangles)), positions_(positions.begin(), positions.end()) {
  if (triangles_.empty()) return;
  order_.resize(triangles_.size());
  std::vector<core::Vec3> centroids(triangles_.size());
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    order_[t] = static_cast<int>(t);
    const auto& tri = triangles_[t];
    centroids[t] = (positions_[tri[0]] + positions_[tri[1]] + positions_[tri[2]]) / 3.0;
  }
  nodes_.reserve(2 * triangles_.size() / kLeafSize + 2);
  build(0, static_cast<int>(triangles_.size()), centroids);
  fit(0);
}

int SurfaceBvh::build(int first, int count, std::vector<core::Vec3>& centroids) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back({});
  if (count <= kLeafSize) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  core::Vec3 lo = core::Vec3::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (int i = first; i < first + count; ++i) {
    lo = lo.cwiseMin(centroids[order_[i]]);
    hi = hi.cwiseMax(centroids[order_[i]]);
  }
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  const int half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half,
                   order_.begin() + first + count,
                   [&](int a, int b) { return centroids[a][axis] < centroids[b][axis]; });
  const int left = build(first, half, centroids);
  const int right = build(first + half, count - half, centroids);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

void SurfaceBvh::fit(int index) {
  Node& node = nodes_[index];
  if (node.count > 0) {
    node.lo = core::Vec3::Constant(std::numeric_limits<double>::max());
    node.hi = -node.lo;
    for (int i = node.first; i < node.first + node.count; ++i) {
      for (const int v : triangles_[order_[i]]) {
        node.lo = node.lo.cwiseMin(positions_[v]);
        node.hi = node.hi.cwiseMax(positions_[v]);
      }
    }
    return;
  }
  fit(node.left);
  fit(node.right);
  Node& again = nodes_[index];  // fit() of the children does not reallocate, but stay explicit
  again.lo = nodes_[again.left].lo.cwiseMin(nodes_[again.right].lo);
  again.hi = nodes_[again.left].hi.cwiseMax(nodes_[again.right].hi);
}

void SurfaceBvh::refit(std::span<const core::Vec3> positions) {
  positions_.assign(positions.begin(), positions.end());
  if (!nodes_.empty()) fit(0);
}

RayHit SurfaceBvh::cast(const core::Vec3& origin, const core::Vec3& direction,
                        double max_distance) const {
  RayHit hit;
  if (nodes_.empty()) return hit;
  double best = max_distance;
  const core::Vec3 inv(1.0 / direction.x(), 1.0 / direction.y(), 1.0 / direction.z());
  std::array<int, 64> stack{};
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (segment_enters_box(origin, direction, inv, node.lo, node.hi, best) > best) continue;
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i) {
        const auto& tri = triangles_[order_[i]];
        const double t = intersect(origin, direction, positions_[tri[0]], positions_[tri[1]],
                                   positions_[tri[2]]);
        if (t <= best) {
          best = t;
          hit.triangle = order_[i];
          hit.distance = t;
        }
      }
      continue;
    }
    // Nearer child last so it is popped first.
    const double l = segment_enters_box(origin, direction, inv, nodes_[node.left].lo,
                                        nodes_[node.left].hi, best);
    const double r = segment_enters_box(origin, direction, inv, nodes_[node.right].lo,
                                        nodes_[node.right].hi, best);
    if (l < r) {
      stack[top++] = node.right;
      stack[top++] = node.left;
    } else {
      stack[top++] = node.left;
      stack[top++] = node.right;
    }
  }
  return hit;
}

NearestPoint SurfaceBvh::nearest(const core::Vec3& point) const {
  NearestPoint out;
  if (nodes_.empty()) return out;
  double best = std::numeric_limits<double>::infinity();
  std::array<int, 64> stack{};
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (box_distance_squared(point, node.lo, node.hi) >= best) continue;
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i) {
        const auto& tri = triangles_[order_[i]];
        std::array<double, 3> bary{};
        const core::Vec3 q = closest_point_on_triangle(
            point, positions_[tri[0]], positions_[tri[1]], positions_[tri[2]], bary);
        const double d2 = (q - point).squaredNorm();
        if (d2 < best) {
          best = d2;
          out.triangle = order_[i];
          out.point = q;
        }
      }
      continue;
    }
    const double l = box_distance_squared(point, nodes_[node.left].lo, nodes_[node.left].hi);
    const double r = box_distance_squared(point, nodes_[node.right].lo, nodes_[node.right].hi);
    if (l < r) {
      stack[top++] = node.right;
      stack[top++] = node.left;
    } else {
      stack[top++] = node.left;
      stack[top++] = node.right;
    }
  }
  out.distance = std::sqrt(best);
  return out;
}

}  // namespace viscera::sim
