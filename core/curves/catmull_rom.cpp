#include "core/curves/catmull_rom.h"

#include <cmath>

#include "core/error.h"

namespace viscera::core {

CatmullRomSpline::CatmullRomSpline(std::vector<Vec3> points, KnotSpacing spacing, bool closed)
    : points_(std::move(points)), spacing_(spacing), closed_(closed) {
  if (points_.size() < (closed_ ? 3U : 2U))
    throw UsageError("a Catmull-Rom spline needs more points");
  for (int i = 0; i < segments(); ++i) {
    if ((point(i + 1) - point(i)).norm() == 0.0)
      throw UsageError("spline points " + std::to_string(i) + " and the next coincide");
  }
}

Vec3 CatmullRomSpline::point(int i) const {
  const auto n = static_cast<int>(points_.size());
  if (closed_) return points_[static_cast<std::size_t>(((i % n) + n) % n)];
  // Open ends: reflect the neighbour so the end tangent points along the first/last chord.
  if (i < 0) return 2.0 * points_.front() - points_[1];
  if (i >= n) return 2.0 * points_.back() - points_[static_cast<std::size_t>(n - 2)];
  return points_[static_cast<std::size_t>(i)];
}

double CatmullRomSpline::knot_gap(int i) const {
  const double chord = (point(i + 1) - point(i)).norm();
  switch (spacing_) {
    case KnotSpacing::Uniform:
      return 1.0;
    case KnotSpacing::Centripetal:
      return std::sqrt(chord);
    case KnotSpacing::ChordLength:
      return chord;
  }
  return 1.0;
}

Vec3 CatmullRomSpline::tangent_at(int i) const {
  // Non-uniform Catmull-Rom tangent (Barry–Goldman): a knot-weighted blend of the chords on
  // either side of point i.
  const double before = knot_gap(i - 1), after = knot_gap(i);
  const Vec3 incoming = (point(i) - point(i - 1)) / before;
  const Vec3 outgoing = (point(i + 1) - point(i)) / after;
  return (after * incoming + before * outgoing) / (before + after);
}

std::array<Vec3, 4> CatmullRomSpline::bezier(int s) const {
  const double gap = knot_gap(s);
  const Vec3 p0 = point(s), p1 = point(s + 1);
  return {p0, p0 + tangent_at(s) * (gap / 3.0), p1 - tangent_at(s + 1) * (gap / 3.0), p1};
}

Vec3 bezier_point(const std::array<Vec3, 4>& b, double t) {
  const double u = 1.0 - t;
  return u * u * u * b[0] + 3.0 * u * u * t * b[1] + 3.0 * u * t * t * b[2] + t * t * t * b[3];
}

Vec3 CatmullRomSpline::evaluate(int s, double t) const {
  return bezier_point(bezier(s), t);
}

Vec3 CatmullRomSpline::derivative(int s, double t) const {
  const auto b = bezier(s);
  const double u = 1.0 - t;
  return 3.0 * (u * u * (b[1] - b[0]) + 2.0 * u * t * (b[2] - b[1]) + t * t * (b[3] - b[2]));
}

std::vector<double> catmull_rom_knot_gaps(const std::vector<Vec3>& points, KnotSpacing spacing,
                                          bool closed) {
  const std::size_t n = points.size();
  if (n < (closed ? 3U : 2U)) throw UsageError("a Catmull-Rom spline needs more points");
  std::vector<double> gaps(closed ? n : n - 1);
  for (std::size_t i = 0; i < gaps.size(); ++i) {
    const double chord = (points[(i + 1) % n] - points[i]).norm();
    if (!(chord > 0.0)) {
      throw UsageError("spline points " + std::to_string(i) + " and " +
                       std::to_string((i + 1) % n) + " coincide");
    }
    switch (spacing) {
      case KnotSpacing::Uniform:
        gaps[i] = 1.0;
        break;
      case KnotSpacing::Centripetal:
        gaps[i] = std::sqrt(chord);
        break;
      case KnotSpacing::ChordLength:
        gaps[i] = chord;
        break;
    }
  }
  return gaps;
}

std::vector<Vec3> catmull_rom_bezier_net(const std::vector<Vec3>& points,
                                         const std::vector<double>& gaps, bool closed) {
  const std::size_t n = points.size();
  const std::size_t segments = closed ? n : n - 1;
  if (n < (closed ? 3U : 2U) || gaps.size() != segments) {
    throw UsageError("Catmull-Rom net: " + std::to_string(gaps.size()) + " knot gaps for " +
                     std::to_string(n) + " points");
  }
  // Tangent at point i with respect to the knot parameter (Barry-Goldman blend of the chords on
  // either side); an open end sees a reflected phantom point, i.e. the first/last chord.
  const auto tangent = [&](std::size_t i) -> Vec3 {
    if (!closed && i == 0) return (points[1] - points[0]) / gaps[0];
    if (!closed && i == n - 1) return (points[n - 1] - points[n - 2]) / gaps[n - 2];
    const std::size_t before_index = (i + n - 1) % n;
    const double before = gaps[closed ? before_index : i - 1], after = gaps[i % segments];
    const Vec3 incoming = (points[i] - points[before_index]) / before;
    const Vec3 outgoing = (points[(i + 1) % n] - points[i]) / after;
    return (after * incoming + before * outgoing) / (before + after);
  };
  std::vector<Vec3> net;
  net.reserve(3 * segments + 1);
  for (std::size_t s = 0; s < segments; ++s) {
    const std::size_t next = (s + 1) % n;
    net.push_back(points[s]);
    net.push_back(points[s] + tangent(s) * (gaps[s] / 3.0));
    net.push_back(points[next] - tangent(next) * (gaps[s] / 3.0));
  }
  net.push_back(closed ? points[0] : points[n - 1]);
  return net;
}

}  // namespace viscera::core
