#include "simulator/cutting/cut_surface_index.h"

#include <algorithm>
#include <cmath>

namespace viscera::sim::cutting {
namespace {

using core::Vec3;

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection, §5.1.5).
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  }
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

}  // namespace

CutSurfaceIndex::CutSurfaceIndex(CutSurface surface, double cell_size)
    : surface_(std::move(surface)), cell_(cell_size) {
  for (const Vec3& v : surface_.vertices)
    bounds_.add(v);
  normals_.reserve(surface_.triangles.size());
  boxes_.resize(surface_.triangles.size());
  for (std::size_t i = 0; i < surface_.triangles.size(); ++i) {
    const auto& t = surface_.triangles[i];
    for (int k : t)
      boxes_[i].add(surface_.vertices[k]);
    const Vec3& a = surface_.vertices[t[0]];
    const Vec3 n = (surface_.vertices[t[1]] - a).cross(surface_.vertices[t[2]] - a);
    normals_.push_back(n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero());
  }
  // Keep the grid bounded: at most ~128 cells along the longest side.
  const double longest = bounds_.size().maxCoeff();
  cell_ = std::max(cell_, longest / 128.0);
  if (!(cell_ > 0.0)) cell_ = 1e-6;
  // A dense grid of at most ~260,000 cells.
  for (;;) {
    origin_ = bounds_.min - Vec3::Constant(cell_);
    double cells = 1.0;
    for (int d = 0; d < 3; ++d) {
      dims_[d] = static_cast<int>(std::ceil((bounds_.size()[d] + 2 * cell_) / cell_)) + 1;
      cells *= dims_[d];
    }
    if (cells <= double(1 << 18)) break;
    cell_ *= 1.01 * std::cbrt(cells / double(1 << 18));
  }
  inverse_cell_ = 1.0 / cell_;
  outer_.add(bounds_.min - Vec3::Constant(1e-9 * cell_));
  outer_.add(bounds_.max + Vec3::Constant(1e-9 * cell_));
  for (int t = 0; t < static_cast<int>(surface_.triangles.size()); ++t) {
    core::BoundingBox box;
    for (int k : surface_.triangles[t])
      box.add(surface_.vertices[k]);
    const auto lo = cell_of(box.min), hi = cell_of(box.max);
    // Only the cells the triangle's plane passes through (a large oblique triangle's box holds
    // many cells it never touches).
    const Vec3& p0 = surface_.vertices[surface_.triangles[t][0]];
    const Vec3& n = normals_[t];
    const double reach = 0.5 * cell_ * n.cwiseAbs().sum() * (1.0 + 1e-9) + 1e-15;
    for (int i = lo[0]; i <= hi[0]; ++i)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int k = lo[2]; k <= hi[2]; ++k) {
          const Vec3 centre = origin_ + (Vec3(i, j, k) + Vec3::Constant(0.5)) * cell_;
          if (std::abs(n.dot(centre - p0)) > reach) continue;
          cells_.emplace_back(key(i, j, k), t);
        }
  }
  std::sort(cells_.begin(), cells_.end());
  // first_[c]: where cell c's triangles start in cells_ (dense, so a column is one range).
  const std::int64_t count = static_cast<std::int64_t>(dims_[0]) * dims_[1] * dims_[2];
  first_.assign(static_cast<std::size_t>(count) + 1, 0);
  for (const auto& [cell, tri] : cells_)
    ++first_[static_cast<std::size_t>(cell) + 1];
  for (std::size_t c = 1; c < first_.size(); ++c)
    first_[c] += first_[c - 1];
  stamp_.assign(surface_.triangles.size(), 0);
}

std::int64_t CutSurfaceIndex::key(int i, int j, int k) const {
  return (static_cast<std::int64_t>(i) * dims_[1] + j) * dims_[2] + k;
}

std::array<int, 3> CutSurfaceIndex::cell_of(const Vec3& p) const {
  std::array<int, 3> c{};
  for (int d = 0; d < 3; ++d) {
    const double x = std::floor((p[d] - origin_[d]) * inverse_cell_);
    c[d] = static_cast<int>(std::clamp(x, 0.0, static_cast<double>(dims_[d] - 1)));
  }
  return c;
}

template <typename Visit>
void CutSurfaceIndex::for_triangles_in(const core::BoundingBox& box, Visit&& visit) const {
  if (box.empty()) return;
  for (int d = 0; d < 3; ++d) {
    if (box.max[d] < bounds_.min[d] - cell_ || box.min[d] > bounds_.max[d] + cell_) return;
  }
  if (++query_ == 0) {
    std::fill(stamp_.begin(), stamp_.end(), 0u);
    query_ = 1;
  }
  const auto lo = cell_of(box.min), hi = cell_of(box.max);
  for (int i = lo[0]; i <= hi[0]; ++i) {
    for (int j = lo[1]; j <= hi[1]; ++j) {
      const int begin = first_[key(i, j, lo[2])], end = first_[key(i, j, hi[2]) + 1];
      for (int e = begin; e < end; ++e) {
        const int tri = cells_[e].second;
        if (stamp_[tri] == query_) continue;
        stamp_[tri] = query_;
        visit(tri);
      }
    }
  }
}

bool CutSurfaceIndex::cells_hold_triangle(const std::array<int, 3>& lo,
                                          const std::array<int, 3>& hi) const {
  for (int i = lo[0]; i <= hi[0]; ++i) {
    for (int j = lo[1]; j <= hi[1]; ++j) {
      if (first_[key(i, j, lo[2])] != first_[key(i, j, hi[2]) + 1]) return true;
    }
  }
  return false;
}

bool CutSurfaceIndex::triangle_may_meet(const std::array<int, 3>& lo, const std::array<int, 3>& hi,
                                        const core::BoundingBox& box) const {
  const Vec3 slack = Vec3::Constant(1e-9 * cell_);
  const Vec3 low = box.min - slack, high = box.max + slack;
  const Vec3 centre = 0.5 * (low + high), half = 0.5 * (high - low);
  for (int i = lo[0]; i <= hi[0]; ++i) {
    for (int j = lo[1]; j <= hi[1]; ++j) {
      const int begin = first_[key(i, j, lo[2])], end = first_[key(i, j, hi[2]) + 1];
      for (int e = begin; e < end; ++e) {
        const int tri = cells_[e].second;
        const core::BoundingBox& b = boxes_[tri];
        if ((b.max.array() < low.array()).any() || (b.min.array() > high.array()).any()) continue;
        const Vec3& n = normals_[tri];
        const Vec3& p0 = surface_.vertices[surface_.triangles[tri][0]];
        if (std::abs(n.dot(centre - p0)) <= half.dot(n.cwiseAbs())) return true;
      }
    }
  }
  return false;
}

std::optional<SegmentCrossing> CutSurfaceIndex::crossing(const Vec3& a, const Vec3& b) const {
  core::BoundingBox box;
  box.add(a);
  box.add(b);
  struct Hit {
    double t;
    int direction;
  };
  Hit hits[16];
  int count = 0;
  const Vec3 dir = b - a;
  for_triangles_in(box, [&](int tri) {
    const auto& f = surface_.triangles[tri];
    const Vec3& p0 = surface_.vertices[f[0]];
    const Vec3 e1 = surface_.vertices[f[1]] - p0, e2 = surface_.vertices[f[2]] - p0;
    const Vec3 h = dir.cross(e2);
    const double det = e1.dot(h);
    if (std::abs(det) < 1e-30) return;  // parallel
    const double inv = 1.0 / det;
    const Vec3 s = a - p0;
    const double u = s.dot(h) * inv;
    constexpr double kEps = 1e-12;
    if (u < -kEps || u > 1.0 + kEps) return;
    const Vec3 q = s.cross(e1);
    const double v = dir.dot(q) * inv;
    if (v < -kEps || u + v > 1.0 + kEps) return;
    const double t = e2.dot(q) * inv;
    if (t < -kEps || t > 1.0 + kEps) return;
    const Hit hit{std::clamp(t, 0.0, 1.0), dir.dot(normals_[tri]) > 0 ? 1 : -1};
    for (int k = 0; k < count; ++k) {
      if (std::abs(hits[k].t - hit.t) < 1e-9) return;  // the same hit on a shared edge
    }
    if (count < 16) hits[count++] = hit;
  });
  if (count % 2 == 0) return std::nullopt;
  std::sort(hits, hits + count, [](const Hit& x, const Hit& y) { return x.t < y.t; });
  const Hit& median = hits[count / 2];
  return SegmentCrossing{median.t, median.direction};
}

std::optional<NearestPoint> CutSurfaceIndex::nearest(const Vec3& p, double radius) const {
  core::BoundingBox box;
  box.add(p - Vec3::Constant(radius));
  box.add(p + Vec3::Constant(radius));
  std::optional<NearestPoint> best;
  for_triangles_in(box, [&](int tri) {
    const auto& f = surface_.triangles[tri];
    const Vec3 c = closest_on_triangle(p, surface_.vertices[f[0]], surface_.vertices[f[1]],
                                       surface_.vertices[f[2]]);
    const double d = (p - c).norm();
    if (d > radius || (best && d >= best->distance)) return;
    best = NearestPoint{d, (p - c).dot(normals_[tri]), c, normals_[tri]};
  });
  return best;
}

}  // namespace viscera::sim::cutting
