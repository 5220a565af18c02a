#include "core/materials/cubic_stress_fit.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "core/random.h"

namespace viscera::core {
namespace {

StressStrainCurve sample(const std::array<double, 4>& cubic, double from, double to, int n) {
  StressStrainCurve curve;
  for (int i = 0; i < n; ++i) {
    const double e = from + (to - from) * i / (n - 1);
    curve.strain.push_back(e);
    curve.stress.push_back(cubic_stress(cubic, e));
  }
  return curve;
}

TEST(CubicStressFit, recovers_known_coefficients_from_exact_samples) {
  const std::array<double, 4> truth = {0.0, 4.0e4, 2.5e5, 6.4e6};
  const CubicStressFit fit = fit_cubic_stress(sample(truth, 0.0, 0.5, 26));
  for (int k = 1; k < 4; ++k)
    EXPECT_NEAR(fit.cubic[k], truth[k], 1e-8 * std::abs(truth[k])) << "c" << k;
  EXPECT_EQ(fit.cubic[0], 0.0);
  EXPECT_LT(fit.rms_error, 1e-6);
  EXPECT_NEAR(fit.r_squared, 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(fit.max_strain, 0.5);
}

TEST(CubicStressFit, recovers_coefficients_within_noise_and_reports_the_noise_level) {
  // Gaussian noise of 500 Pa on a curve reaching ~1 MPa: the RMS error estimates the noise and
  // the coefficients stay within a few standard errors.
  const std::array<double, 4> truth = {0.0, 1.0e5, -1.0e5, 2.7e5};
  StressStrainCurve curve = sample(truth, 0.0, 1.4, 400);
  Rng rng(11);
  for (auto& s : curve.stress)
    s += rng.normal(0.0, 500.0);
  const CubicStressFit fit = fit_cubic_stress(curve);
  EXPECT_NEAR(fit.rms_error, 500.0, 50.0);
  EXPECT_GT(fit.max_error, 2.0 * fit.rms_error);
  EXPECT_LT(fit.max_error, 5.0 * 500.0);
  EXPECT_NEAR(fit.cubic[1], truth[1], 1.5e3);
  EXPECT_NEAR(fit.cubic[2], truth[2], 4.0e3);
  EXPECT_NEAR(fit.cubic[3], truth[3], 2.5e3);
}

TEST(CubicStressFit, odd_model_fits_tension_and_compression_as_the_simulator_springs_do) {
  const std::array<double, 4> truth = {0.0, 3.0e4, 1.0e5, 5.0e5};
  const CubicStressFit fit = fit_cubic_stress(sample(truth, -0.3, 0.3, 31));
  EXPECT_NEAR(fit.cubic[2], truth[2], 1e-6 * truth[2]);
  // Compression pushes exactly as hard as the same stretch pulls.
  EXPECT_DOUBLE_EQ(cubic_stress(fit.cubic, -0.2), -cubic_stress(fit.cubic, 0.2));
}

TEST(CubicStressFit, max_error_names_the_worst_sample) {
  StressStrainCurve curve = sample({0.0, 1.0e4, 0.0, 1.0e5}, 0.0, 0.4, 9);
  curve.stress[6] += 2000.0;
  const CubicStressFit fit = fit_cubic_stress(curve);
  EXPECT_EQ(fit.max_error_sample, 6u);
  EXPECT_GT(fit.max_error, fit.rms_error);
}

TEST(CubicStressFit, with_cubic_fit_fills_the_curve) {
  const StressStrainCurve curve = with_cubic_fit(sample({0.0, 2.0e4, 0.0, 3.0e5}, 0.0, 0.3, 10));
  ASSERT_EQ(curve.cubic.size(), 4u);
  EXPECT_NEAR(curve.cubic[3], 3.0e5, 1e-3);
  EXPECT_LT(curve.fit_rms_error, 1e-6);
  EXPECT_LE(curve.fit_rms_error, curve.fit_max_error + 1e-12);
}

TEST(CubicStressFit, refuses_curves_that_cannot_determine_a_cubic) {
  StressStrainCurve three;
  three.strain = {0.0, 0.1, 0.2};
  three.stress = {0.0, 1.0, 2.0};
  EXPECT_THROW(fit_cubic_stress(three), UsageError);
  StressStrainCurve repeated;
  repeated.strain = {0.0, 0.1, 0.1, -0.1, 0.2};
  repeated.stress = {0.0, 1.0, 1.1, -1.0, 2.0};
  EXPECT_THROW(fit_cubic_stress(repeated), InputError);
  StressStrainCurve mismatched;
  mismatched.strain = {0.1, 0.2, 0.3, 0.4};
  mismatched.stress = {1.0, 2.0, 3.0};
  EXPECT_THROW(fit_cubic_stress(mismatched), UsageError);
}

}  // namespace
}  // namespace viscera::core
