#include "simulator/haptics/proxy_surface_tree.h"

#include <algorithm>
#include <array>
#include <limits>

#include "simulator/collision/penetration_depth.h"
#include "simulator/collision/segment_box.h"

namespace viscera::sim {

namespace {

constexpr int kLeafFaces = 4;

}  // namespace

ProxySurfaceTree::ProxySurfaceTree(std::span<const core::Triangle> faces,
                                   std::span<const core::Vec3> positions) {
  if (faces.empty()) return;
  std::vector<core::Vec3> centroids(faces.size());
  for (std::size_t t = 0; t < faces.size(); ++t)
    centroids[t] = (positions[faces[t][0]] + positions[faces[t][1]] + positions[faces[t][2]]) / 3.0;
  order_.resize(faces.size());
  for (std::size_t t = 0; t < faces.size(); ++t)
    order_[t] = static_cast<int>(t);
  nodes_.reserve(2 * faces.size() / kLeafFaces + 1);
  build(0, static_cast<int>(faces.size()), centroids);
  leaf_vertex_start_.push_back(0);
  for (const Node& node : nodes_) {
    if (node.count == 0) continue;
    const auto first = leaf_vertices_.end() - leaf_vertices_.begin();
    for (int k = node.first; k < node.first + node.count; ++k)
      for (const int v : faces[static_cast<std::size_t>(order_[static_cast<std::size_t>(k)])])
        leaf_vertices_.push_back(v);
    std::sort(leaf_vertices_.begin() + first, leaf_vertices_.end());
    leaf_vertices_.erase(std::unique(leaf_vertices_.begin() + first, leaf_vertices_.end()),
                         leaf_vertices_.end());
    leaf_vertex_start_.push_back(static_cast<int>(leaf_vertices_.size()));
  }
  refit(positions);
}

int ProxySurfaceTree::build(int first, int count, std::vector<core::Vec3>& centroids) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  if (count <= kLeafFaces) {
    nodes_[static_cast<std::size_t>(index)].first = first;
    nodes_[static_cast<std::size_t>(index)].count = count;
    return index;
  }
  // Split at the median centroid along the longest side of the centroids' box.
  core::Vec3 lo = core::Vec3::Constant(std::numeric_limits<double>::infinity());
  core::Vec3 hi = -lo;
  const auto begin = order_.begin() + first;
  for (auto it = begin; it != begin + count; ++it) {
    lo = lo.cwiseMin(centroids[static_cast<std::size_t>(*it)]);
    hi = hi.cwiseMax(centroids[static_cast<std::size_t>(*it)]);
  }
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  const int half = count / 2;
  std::nth_element(begin, begin + half, begin + count, [&](int a, int b) {
    const double ca = centroids[static_cast<std::size_t>(a)][axis];
    const double cb = centroids[static_cast<std::size_t>(b)][axis];
    return ca < cb || (ca == cb && a < b);
  });
  build(first, half, centroids);
  const int right = build(first + half, count - half, centroids);
  nodes_[static_cast<std::size_t>(index)].right = right;
  return index;
}

void ProxySurfaceTree::refit(std::span<const core::Vec3> positions) {
  moved_ = false;
  const core::Vec3 pad = core::Vec3::Constant(kPadding);
  // Children come after their parent: fit from the last node back (and the last leaf back).
  auto leaf = static_cast<std::ptrdiff_t>(leaf_vertex_start_.size()) - 1;
  for (std::size_t n = nodes_.size(); n-- > 0;) {
    Node& node = nodes_[n];
    if (node.count > 0) {
      --leaf;
      const int first = leaf_vertex_start_[static_cast<std::size_t>(leaf)];
      const int end = leaf_vertex_start_[static_cast<std::size_t>(leaf) + 1];
      core::Vec3 lo = positions[static_cast<std::size_t>(leaf_vertices_[first])], hi = lo;
      for (int k = first + 1; k < end; ++k) {
        const core::Vec3& p = positions[static_cast<std::size_t>(leaf_vertices_[k])];
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
      node.lo = lo - pad;
      node.hi = hi + pad;
    } else {
      const Node& left = nodes_[n + 1];
      const Node& right = nodes_[static_cast<std::size_t>(node.right)];
      node.lo = left.lo.cwiseMin(right.lo);
      node.hi = left.hi.cwiseMax(right.hi);
    }
  }
}

template <typename Visit, typename Reach>
void ProxySurfaceTree::along_segment(const core::Vec3& p, const core::Vec3& q, Reach reach,
                                     Visit visit) const {
  if (nodes_.empty()) return;
  const core::Vec3 d = q - p;
  const core::Vec3 inverse = d.cwiseInverse();
  std::array<int, 128> stack{};
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const int n = stack[--top];
    const Node& node = nodes_[static_cast<std::size_t>(n)];
    if (segment_enters_box(p, d, inverse, node.lo, node.hi, reach()) ==
        std::numeric_limits<double>::infinity())
      continue;
    if (node.count > 0) {
      for (int k = node.first; k < node.first + node.count; ++k)
        visit(order_[static_cast<std::size_t>(k)]);
    } else {
      stack[top++] = node.right;
      stack[top++] = n + 1;
    }
  }
}

ProxySurfaceTree::Entry ProxySurfaceTree::first_entry(const core::Vec3& p, const core::Vec3& q,
                                                      std::span<const core::Triangle> faces,
                                                      std::span<const core::Vec3> x) {
  if (moved_) refit(x);
  Entry best;
  const core::Vec3 d = q - p;
  along_segment(
      p, q, [&] { return best.face < 0 ? 1.0 : best.s; },
      [&](int t) {
        const core::Triangle& f = faces[static_cast<std::size_t>(t)];
        const core::Vec3 &a = x[f[0]], &b = x[f[1]], &c = x[f[2]];
        if (d.dot((b - a).cross(c - a)) >= 0.0) return;  // leaving or grazing
        const double s = segment_triangle_intersection(p, q, a, b, c);
        if (s < 0.0) return;
        if (best.face < 0 || s < best.s || (s == best.s && t < best.face)) best = {t, s};
      });
  return best;
}

int ProxySurfaceTree::crossings(const core::Vec3& p, const core::Vec3& q,
                                std::span<const core::Triangle> faces,
                                std::span<const core::Vec3> x) {
  if (moved_) refit(x);
  int count = 0;
  along_segment(
      p, q, [] { return 1.0; },
      [&](int t) {
        const core::Triangle& f = faces[static_cast<std::size_t>(t)];
        if (segment_triangle_intersection(p, q, x[f[0]], x[f[1]], x[f[2]]) >= 0.0) ++count;
      });
  return count;
}

}  // namespace viscera::sim
