#include "core/curves/cubic_curve.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace viscera::core {

CubicCurve::CubicCurve(std::vector<Vec3> net, std::vector<double> gaps, bool closed)
    : net_(std::move(net)), gaps_(std::move(gaps)), closed_(closed) {
  if (gaps_.empty() || net_.size() != 3 * gaps_.size() + 1) {
    throw UsageError("a cubic curve needs 3·segments + 1 control points, got " +
                     std::to_string(net_.size()) + " for " + std::to_string(gaps_.size()) +
                     " segments");
  }
  for (std::size_t i = 0; i < net_.size(); ++i) {
    if (!net_[i].allFinite())
      throw UsageError("curve control point " + std::to_string(i) + " is not finite");
  }
  knots_.assign(1, 0.0);
  for (std::size_t s = 0; s < gaps_.size(); ++s) {
    if (!(gaps_[s] > 0.0) || !std::isfinite(gaps_[s])) {
      throw UsageError("knot gap of curve segment " + std::to_string(s) + " must be positive");
    }
    knots_.push_back(knots_.back() + gaps_[s]);
  }
}

std::array<Vec3, 4> CubicCurve::bezier(int s) const {
  const auto i = static_cast<std::size_t>(3 * s);
  return {net_[i], net_[i + 1], net_[i + 2], net_[i + 3]};
}

std::pair<int, double> CubicCurve::locate(double t) const {
  const double end = knots_.back();
  if (closed_) {
    t = std::fmod(t, end);
    if (t < 0.0) t += end;
  } else {
    t = std::clamp(t, 0.0, end);
  }
  // upper_bound finds the first knot after t; the segment starts one before it.
  const auto it = std::upper_bound(knots_.begin(), knots_.end(), t);
  const int s = std::clamp(static_cast<int>(it - knots_.begin()) - 1, 0, segments() - 1);
  const double u = std::clamp(
      (t - knots_[static_cast<std::size_t>(s)]) / gaps_[static_cast<std::size_t>(s)], 0.0, 1.0);
  return {s, u};
}

Vec3 CubicCurve::point(double t) const {
  const auto [s, u] = locate(t);
  return bezier_point(bezier(s), u);
}

Vec3 CubicCurve::derivative(double t) const {
  const auto [s, u] = locate(t);
  const auto b = bezier(s);
  const double v = 1.0 - u;
  const Vec3 d =
      3.0 * (v * v * (b[1] - b[0]) + 2.0 * v * u * (b[2] - b[1]) + u * u * (b[3] - b[2]));
  return d / gaps_[static_cast<std::size_t>(s)];
}

Vec3 CubicCurve::second_derivative(double t) const {
  const auto [s, u] = locate(t);
  const auto b = bezier(s);
  const Vec3 d2 = 6.0 * ((1.0 - u) * (b[2] - 2.0 * b[1] + b[0]) + u * (b[3] - 2.0 * b[2] + b[1]));
  const double gap = gaps_[static_cast<std::size_t>(s)];
  return d2 / (gap * gap);
}

Vec3 CubicCurve::tangent(double t) const {
  const Vec3 d = derivative(t);
  const double length = d.norm();
  if (length > 1e-14 * (1.0 + point(t).norm())) return d / length;
  // A cusp or a coinciding handle: fall back to the chord of the segment.
  const auto b = bezier(locate(t).first);
  const Vec3 chord = b[3] - b[0];
  return chord.norm() > 0.0 ? Vec3(chord.normalized()) : Vec3::UnitZ();
}

CubicCurve catmull_rom_curve(const std::vector<Vec3>& points, KnotSpacing spacing, bool closed) {
  std::vector<double> gaps = catmull_rom_knot_gaps(points, spacing, closed);
  std::vector<Vec3> net = catmull_rom_bezier_net(points, gaps, closed);
  return CubicCurve(std::move(net), std::move(gaps), closed);
}

CubicCurve cubic_bspline_curve(const std::vector<Vec3>& control, bool closed) {
  const auto n = static_cast<int>(control.size());
  if (n < (closed ? 3 : 2))
    throw UsageError("a cubic B-spline needs at least " + std::string(closed ? "3" : "2") +
                     " control points");
  const auto at = [&](int i) -> Vec3 {
    if (closed) return control[static_cast<std::size_t>(((i % n) + n) % n)];
    if (i < 0) return 2.0 * control.front() - control[1];
    if (i >= n) return 2.0 * control.back() - control[static_cast<std::size_t>(n - 2)];
    return control[static_cast<std::size_t>(i)];
  };
  const int segments = closed ? n : n - 1;
  std::vector<Vec3> net;
  net.reserve(static_cast<std::size_t>(3 * segments + 1));
  // Each uniform B-spline span over (P_{i−1}, P_i, P_{i+1}, P_{i+2}) in Bézier form (Böhm).
  for (int i = 0; i < segments; ++i) {
    const Vec3 a = at(i - 1), b = at(i), c = at(i + 1);
    net.push_back((a + 4.0 * b + c) / 6.0);
    net.push_back((2.0 * b + c) / 3.0);
    net.push_back((b + 2.0 * c) / 3.0);
  }
  net.push_back((at(segments - 1) + 4.0 * at(segments) + at(segments + 1)) / 6.0);
  return CubicCurve(std::move(net), std::vector<double>(static_cast<std::size_t>(segments), 1.0),
                    closed);
}

CubicCurve hermite_curve(const std::vector<Vec3>& points, const std::vector<Vec3>& tangents,
                         std::vector<double> gaps, bool closed) {
  const std::size_t n = points.size();
  if (n < (closed ? 3U : 2U)) throw UsageError("a Hermite curve needs more points");
  if (tangents.size() != n) throw UsageError("a Hermite curve needs one tangent per point");
  const std::size_t segments = closed ? n : n - 1;
  if (gaps.empty()) gaps.assign(segments, 1.0);
  if (gaps.size() != segments) throw UsageError("a Hermite curve needs one knot gap per segment");
  std::vector<Vec3> net;
  net.reserve(3 * segments + 1);
  for (std::size_t s = 0; s < segments; ++s) {
    const std::size_t next = (s + 1) % n;
    net.push_back(points[s]);
    net.push_back(points[s] + tangents[s] * (gaps[s] / 3.0));
    net.push_back(points[next] - tangents[next] * (gaps[s] / 3.0));
  }
  net.push_back(points[closed ? 0 : n - 1]);
  return CubicCurve(std::move(net), std::move(gaps), closed);
}

}  // namespace viscera::core
