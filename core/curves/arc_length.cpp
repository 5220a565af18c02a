#include "core/curves/arc_length.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.h"

namespace viscera::core {
namespace {

// 5-point Gauss-Legendre nodes and weights on [-1, 1].
constexpr std::array<double, 5> kNodes = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                          0.5384693101056831, 0.9061798459386640};
constexpr std::array<double, 5> kWeights = {0.2369268850561891, 0.4786286704993665,
                                            0.5688888888888889, 0.4786286704993665,
                                            0.2369268850561891};

}  // namespace

ArcLengthTable::ArcLengthTable(CubicCurve curve, int samples_per_segment)
    : curve_(std::move(curve)) {
  if (samples_per_segment < 1)
    throw UsageError("arc-length table needs at least one sample per segment");
  parameters_.push_back(0.0);
  lengths_.push_back(0.0);
  for (int s = 0; s < curve_.segments(); ++s) {
    const double t0 = curve_.knot(s), t1 = curve_.knot(s + 1);
    for (int k = 1; k <= samples_per_segment; ++k) {
      const double a = t0 + (t1 - t0) * (k - 1) / samples_per_segment;
      const double b = k == samples_per_segment ? t1 : t0 + (t1 - t0) * k / samples_per_segment;
      parameters_.push_back(b);
      lengths_.push_back(lengths_.back() + integrate(a, b));
    }
  }
}

double ArcLengthTable::integrate(double t0, double t1) const {
  // Callers pass intervals inside one segment, where |C'| is smooth; the Gauss nodes are
  // interior points, so each evaluation finds that segment.
  const double half = 0.5 * (t1 - t0), mid = 0.5 * (t0 + t1);
  double sum = 0.0;
  for (std::size_t i = 0; i < kNodes.size(); ++i)
    sum += kWeights[i] * curve_.derivative(mid + half * kNodes[i]).norm();
  return sum * half;
}

double ArcLengthTable::length_at(double t) const {
  t = std::clamp(t, 0.0, parameters_.back());
  const auto it = std::upper_bound(parameters_.begin(), parameters_.end(), t);
  const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(it - parameters_.begin()),
                                              parameters_.size()) -
                        1;
  if (i + 1 >= parameters_.size()) return lengths_.back();
  return lengths_[i] + integrate(parameters_[i], t);
}

double ArcLengthTable::parameter_at(double s) const {
  s = std::clamp(s, 0.0, lengths_.back());
  const auto it = std::upper_bound(lengths_.begin(), lengths_.end(), s);
  std::size_t i = static_cast<std::size_t>(it - lengths_.begin());
  if (i == 0) return 0.0;
  if (i >= lengths_.size()) return parameters_.back();
  --i;
  double lo = parameters_[i], hi = parameters_[i + 1];
  const double span = lengths_[i + 1] - lengths_[i];
  double t = span > 0.0 ? lo + (hi - lo) * (s - lengths_[i]) / span : lo;
  // Newton on f(t) = length_at(t) − s with f' = |C'(t)|, kept inside the bracket [lo, hi] by
  // bisection whenever a step leaves it or the speed vanishes.
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double f = lengths_[i] + integrate(parameters_[i], t) - s;
    if (std::abs(f) <= 1e-13 * (1.0 + lengths_.back())) break;
    if (f > 0.0)
      hi = t;
    else
      lo = t;
    const double speed = curve_.derivative(t).norm();
    double next = speed > 0.0 ? t - f / speed : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == t) break;
    t = next;
  }
  return t;
}

std::vector<double> even_arc_length_parameters(const ArcLengthTable& table, int n) {
  if (n < 1) throw UsageError("even arc-length sampling needs at least one interval");
  std::vector<double> parameters(static_cast<std::size_t>(n) + 1);
  for (int k = 0; k <= n; ++k)
    parameters[static_cast<std::size_t>(k)] = table.parameter_at(table.length() * k / n);
  parameters.front() = 0.0;
  parameters.back() = table.curve().parameter_end();
  return parameters;
}

}  // namespace viscera::core
