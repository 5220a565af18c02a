#pragma once
/// Arc-length parametrisation of piecewise cubic curves: lengths by Gauss-Legendre quadrature
/// of |C'(t)| and the inverse map s → t by safeguarded Newton steps, so pipes and vessels can
/// be sampled at even spacing in m (seed 001 §3.3 flexible pipes).

#include <vector>

#include "core/curves/cubic_curve.h"

namespace viscera::core {

/// Cumulative arc length of a curve, tabulated at `samples_per_segment` sub-intervals of every
/// segment; between table entries the length is integrated exactly to quadrature precision
/// (5-point Gauss-Legendre, error ~1e-10 relative for smooth segments).
class ArcLengthTable {
 public:
  /// Keeps a copy of `curve`. samples_per_segment ≥ 1; throws UsageError otherwise.
  explicit ArcLengthTable(CubicCurve curve, int samples_per_segment = 16);

  const CubicCurve& curve() const { return curve_; }
  /// Total length in m.
  double length() const { return lengths_.back(); }
  /// Length in m from the start to knot parameter t (t clamped to the parameter range).
  double length_at(double t) const;
  /// Knot parameter where the length from the start equals s (s clamped to [0, length()]).
  double parameter_at(double s) const;

 private:
  double integrate(double t0, double t1) const;

  CubicCurve curve_;
  std::vector<double> parameters_;  ///< tabulated knot parameters, increasing
  std::vector<double> lengths_;     ///< arc length at each tabulated parameter
};

/// n + 1 knot parameters (n ≥ 1) evenly spaced in arc length from the start to the end.
std::vector<double> even_arc_length_parameters(const ArcLengthTable& table, int n);

}  // namespace viscera::core
