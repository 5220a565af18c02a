#include "core/materials/material_constants.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "core/materials/cubic_stress_fit.h"
#include "core/materials/shipped_materials.h"

namespace viscera::core {
namespace {

TEST(MaterialConstants, linear_tissue_gives_the_lame_parameters_of_the_edge_network) {
  // A linear tissue (c2 = c3 = 0) of E = 60 kPa, ν = 0.45.
  const std::array<double, 4> cubic = {0.0, 6.0e4, 0.0, 0.0};
  ElasticityOptions options;
  options.poisson_ratio = 0.45;
  const TeschnerConstants k = teschner_constants(cubic, 0.2, options);
  EXPECT_DOUBLE_EQ(k.linear_modulus, 6.0e4);
  const double mu = 6.0e4 / 2.9, lambda = 6.0e4 * 0.45 / (1.45 * 0.1);
  // The network's μ is s/15 and its λ is s/15 + v.
  EXPECT_NEAR(k.distance_stiffness / 15.0, mu, 1e-9 * mu);
  EXPECT_NEAR(k.distance_stiffness / 15.0 + k.volume_stiffness, lambda, 1e-9 * lambda);
  EXPECT_EQ(k.area_stiffness, 0.0);
}

TEST(MaterialConstants, poisson_quarter_needs_no_volume_terms_and_gives_six_times_the_modulus) {
  const TeschnerConstants k = teschner_constants({0.0, 1.0e4, 0.0, 0.0}, 0.1, {0.25, 0.0, 0.0});
  EXPECT_NEAR(k.volume_stiffness, 0.0, 1e-9);
  EXPECT_NEAR(k.distance_stiffness, 6.0e4, 1e-6);
}

TEST(MaterialConstants, linearised_modulus_is_the_least_squares_line_of_the_cubic) {
  const std::array<double, 4> cubic = {0.0, 2.0e4, 3.0e4, 5.0e5};
  const double w = 0.4;
  // Numerical ∫σε / ∫ε² by the midpoint rule.
  double num = 0.0, den = 0.0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const double e = (i + 0.5) * w / n;
    num += cubic_stress(cubic, e) * e;
    den += e * e;
  }
  EXPECT_NEAR(linearised_modulus(cubic, w), num / den, 1e-6 * num / den);
}

TEST(MaterialConstants, membrane_gives_area_stiffness) {
  const TeschnerConstants k = teschner_constants({0.0, 1.0e5, 0.0, 0.0}, 0.1, {0.45, 0.0, 2.0e-4});
  EXPECT_NEAR(k.area_stiffness, 1.0e5 * 2.0e-4 / 1.1, 1e-9);
}

TEST(MaterialConstants, softening_fit_is_refused_and_bad_options_are_usage_errors) {
  // Tangent 1e4 − 2·1e5 ε·… falls below zero inside [0, 0.5].
  EXPECT_THROW(teschner_constants({0.0, 1.0e4, -1.0e5, 0.0}, 0.5, {}), ValidationError);
  EXPECT_THROW(teschner_constants({0.0, 1.0e4, 0.0, 0.0}, 0.5, {0.5, 0.0, 0.0}), UsageError);
  EXPECT_THROW(teschner_constants({0.0, 1.0e4, 0.0, 0.0}, 0.5, {0.2, 0.0, 0.0}), UsageError);
  EXPECT_THROW(teschner_constants({0.0, 1.0e4, 0.0, 0.0}, 0.0, {}), UsageError);
}

TEST(MaterialConstants, strain_at_stress_inverts_the_cubic) {
  const std::array<double, 4> cubic = {0.0, 4.0e4, 0.0, 6.4e6};
  const double e = strain_at_stress(cubic, 1.0e6, 10.0);
  EXPECT_NEAR(cubic_stress(cubic, e), 1.0e6, 1e-3);
  EXPECT_EQ(strain_at_stress(cubic, 1.0e12, 2.0), 2.0);
}

TEST(MaterialConstants, material_from_measured_curve_keeps_base_and_fills_fit) {
  StressStrainCurve curve;
  for (int i = 0; i <= 10; ++i) {
    curve.strain.push_back(0.05 * i);
    curve.stress.push_back(cubic_stress({0.0, 3.0e4, 0.0, 2.0e6}, 0.05 * i));
  }
  Material base;
  base.id = "measured";
  base.density = 1040.0;
  base.tearing_threshold = 0.7;
  const Material m = material_from_measured_curve(curve, {}, base);
  EXPECT_EQ(m.id, "measured");
  EXPECT_EQ(m.density, 1040.0);
  EXPECT_EQ(m.tearing_threshold, 0.7);
  ASSERT_TRUE(m.stress_strain);
  EXPECT_NEAR(m.stress_strain->cubic[3], 2.0e6, 1.0);
  const double e = linearised_modulus({0.0, 3.0e4, 0.0, 2.0e6}, 0.5);
  EXPECT_NEAR(m.distance_stiffness, 15.0 * e / 2.9, 1e-3 * e);
}

}  // namespace
}  // namespace viscera::core
