#include "core/materials/cubic_stress_fit.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <set>

#include "core/error.h"

namespace viscera::core {

double cubic_stress(const std::array<double, 4>& c, double e) {
  return c[1] * e + c[2] * e * std::abs(e) + c[3] * e * e * e;
}

double cubic_tangent_modulus(const std::array<double, 4>& c, double e) {
  return c[1] + 2.0 * c[2] * std::abs(e) + 3.0 * c[3] * e * e;
}

CubicStressFit fit_cubic_stress(const StressStrainCurve& curve) {
  const std::size_t n = curve.strain.size();
  if (curve.stress.size() != n) {
    throw UsageError("a stress-strain curve needs one stress per strain (" + std::to_string(n) +
                     " strains, " + std::to_string(curve.stress.size()) + " stresses)");
  }
  if (n < 4) throw UsageError("a cubic fit needs at least 4 samples, got " + std::to_string(n));

  CubicStressFit fit;
  std::set<double> distinct;
  for (const double e : curve.strain) {
    fit.max_strain = std::max(fit.max_strain, std::abs(e));
    if (e != 0.0) distinct.insert(std::abs(e));
  }
  if (distinct.size() < 3) {
    throw InputError("the curve has " + std::to_string(distinct.size()) +
                     " distinct non-zero strains; a cubic through the origin needs at least 3");
  }

  // Columns scaled to unit strain range so the three basis functions are of similar size.
  const double s = fit.max_strain;
  Eigen::MatrixXd a(static_cast<Eigen::Index>(n), 3);
  Eigen::VectorXd b(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const double x = curve.strain[i] / s;
    const auto r = static_cast<Eigen::Index>(i);
    a(r, 0) = x;
    a(r, 1) = x * std::abs(x);
    a(r, 2) = x * x * x;
    b(r) = curve.stress[i];
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  if (qr.rank() < 3) throw InputError("the strains do not determine the three cubic coefficients");
  const Eigen::Vector3d scaled = qr.solve(b);
  fit.cubic = {0.0, scaled(0) / s, scaled(1) / (s * s), scaled(2) / (s * s * s)};

  double mean = 0.0;
  for (const double y : curve.stress)
    mean += y;
  mean /= static_cast<double>(n);
  double ss_res = 0.0, ss_tot = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double residual = curve.stress[i] - cubic_stress(fit.cubic, curve.strain[i]);
    ss_res += residual * residual;
    ss_tot += (curve.stress[i] - mean) * (curve.stress[i] - mean);
    if (std::abs(residual) > fit.max_error) {
      fit.max_error = std::abs(residual);
      fit.max_error_sample = i;
    }
  }
  fit.rms_error = std::sqrt(ss_res / static_cast<double>(n));
  fit.r_squared = ss_tot > 0.0 ? 1.0 - ss_res / ss_tot : 1.0;
  return fit;
}

StressStrainCurve with_cubic_fit(StressStrainCurve curve) {
  const CubicStressFit fit = fit_cubic_stress(curve);
  curve.cubic.assign(fit.cubic.begin(), fit.cubic.end());
  curve.fit_rms_error = fit.rms_error;
  curve.fit_max_error = fit.max_error;
  return curve;
}

}  // namespace viscera::core
