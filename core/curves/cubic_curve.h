#pragma once
/// Piecewise cubic curves in Bézier form: the one representation in which Catmull-Rom, cubic
/// B-spline and Hermite curves are evaluated, measured and swept (seed 002 §3.1: "only the
/// piece-wise Bézier or Hermite interpolations satisfy the above requirements"; seed 001 §3.3:
/// flexible pipes along spline curves). Positions in m.
///
/// The curve parameter t is the knot parameter: segment s spans [knot(s), knot(s+1)], so
/// derivatives are with respect to the knots (for chord-length knots t is close to arc length).

#include <array>
#include <vector>

#include "core/curves/catmull_rom.h"
#include "core/math_types.h"

namespace viscera::core {

/// A C0-joined sequence of cubic Bézier segments with a knot interval per segment.
class CubicCurve {
 public:
  /// `net` holds 3·segments + 1 control points (segment s uses net[3s … 3s+3]) and `gaps` the
  /// positive knot interval of each segment. A closed curve's net ends on its first point.
  /// Throws UsageError when the sizes disagree, a gap is not positive, or a point is not finite.
  CubicCurve(std::vector<Vec3> net, std::vector<double> gaps, bool closed);

  int segments() const { return static_cast<int>(gaps_.size()); }
  bool closed() const { return closed_; }
  /// Knot at the start of segment s; knot(segments()) is the end of the parameter range.
  double knot(int s) const { return knots_[static_cast<std::size_t>(s)]; }
  double parameter_end() const { return knots_.back(); }
  /// The four Bézier control points of segment s.
  std::array<Vec3, 4> bezier(int s) const;
  const std::vector<Vec3>& control_net() const { return net_; }
  const std::vector<double>& knot_gaps() const { return gaps_; }

  /// Point at knot parameter t (clamped to the range; wrapped when closed).
  Vec3 point(double t) const;
  /// First and second derivatives with respect to the knot parameter (m per unit of t).
  Vec3 derivative(double t) const;
  Vec3 second_derivative(double t) const;
  /// Unit tangent at t; the chord of the segment where the derivative vanishes.
  Vec3 tangent(double t) const;

  /// Segment holding t and the local Bézier parameter u ∈ [0, 1] there. At an interior knot
  /// the later segment is chosen.
  std::pair<int, double> locate(double t) const;

 private:
  std::vector<Vec3> net_;
  std::vector<double> gaps_;
  std::vector<double> knots_;
  bool closed_;
};

/// Catmull-Rom curve through `points` (seed 002 §3.1; chord-length spacing is the seed's
/// choice). Throws UsageError for too few points or coinciding neighbours.
CubicCurve catmull_rom_curve(const std::vector<Vec3>& points, KnotSpacing spacing, bool closed);

/// Uniform cubic B-spline with control points `control` (unit knot gaps). It approximates its
/// control points (C2 everywhere); an open curve starts at the first and ends at the last
/// control point (reflected phantom points), a closed one wraps. Needs ≥ 2 points (≥ 3 closed).
CubicCurve cubic_bspline_curve(const std::vector<Vec3>& control, bool closed);

/// Cubic Hermite curve through `points` with derivatives `tangents` (m per unit of knot
/// parameter) at the points and knot gaps `gaps` (empty = all 1). Throws UsageError when the
/// sizes disagree.
CubicCurve hermite_curve(const std::vector<Vec3>& points, const std::vector<Vec3>& tangents,
                         std::vector<double> gaps, bool closed);

}  // namespace viscera::core
