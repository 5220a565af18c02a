#pragma once
/// Catmull-Rom splines through points, evaluated as piecewise cubic Bézier segments (seed 002
/// §3.1: "the control points are calculated by the Catmull–Rom method … the knot sequence is
/// created using the chord length method"). Knots may be uniform, centripetal or chord-length
/// (parameter spacing |P_{i+1} − P_i|^α with α = 0, ½, 1); closed curves wrap around.

#include <array>
#include <vector>

#include "core/math_types.h"

namespace viscera::core {

/// Knot spacing of a Catmull-Rom spline.
enum class KnotSpacing { Uniform, Centripetal, ChordLength };

/// An interpolating cubic spline: it passes through every point with a continuous tangent.
class CatmullRomSpline {
 public:
  /// `points` (≥ 2, or ≥ 3 when closed). Open curves get end tangents from a reflected phantom
  /// point. Throws UsageError for too few points or two equal neighbours.
  CatmullRomSpline(std::vector<Vec3> points, KnotSpacing spacing, bool closed);

  /// Number of segments: points − 1 when open, points when closed.
  int segments() const { return static_cast<int>(closed_ ? points_.size() : points_.size() - 1); }
  /// The four Bézier control points of segment s (from point s to point s + 1).
  std::array<Vec3, 4> bezier(int s) const;
  /// Point on segment s at local parameter t ∈ [0, 1].
  Vec3 evaluate(int s, double t) const;
  /// Derivative with respect to t on segment s.
  Vec3 derivative(int s, double t) const;

 private:
  Vec3 point(int i) const;
  double knot_gap(int i) const;  ///< parameter length of segment i (between points i and i+1)
  Vec3 tangent_at(int i) const;  ///< derivative with respect to the knot parameter at point i

  std::vector<Vec3> points_;
  KnotSpacing spacing_;
  bool closed_;
};

/// Bézier point at t of control points b (de Casteljau).
Vec3 bezier_point(const std::array<Vec3, 4>& b, double t);

/// Parameter length of each segment, |P_{i+1} − P_i|^α for the spacing's α: points − 1 gaps
/// when open, points when closed (the last one closes the loop). Throws UsageError naming the
/// pair when two neighbouring points coincide, or when there are too few points.
std::vector<double> catmull_rom_knot_gaps(const std::vector<Vec3>& points, KnotSpacing spacing,
                                          bool closed);

/// The Bézier control net of the Catmull-Rom spline through `points` with the given knot gaps
/// (as from catmull_rom_knot_gaps, or averaged over the rows of a surface grid): 3·segments + 1
/// points, segment s using net[3s … 3s+3]; a closed net repeats the first point at its end.
/// Open ends take the tangent of the first/last chord, as CatmullRomSpline does. The net is
/// linear in the points for fixed gaps, which is what lets a bicubic surface apply it to rows
/// and then to columns of control points. Throws UsageError when the gap count does not match.
std::vector<Vec3> catmull_rom_bezier_net(const std::vector<Vec3>& points,
                                         const std::vector<double>& gaps, bool closed);

}  // namespace viscera::core
