// Artificial vortices on the cavity flow (seed 000 §2.2): each is a Lamb–Oseen vortex — its
// speed profile analytic, its field divergence-free and tangential; they appear only above the
// inflow threshold, more with more inflow up to the cap, fade over their lifetime, and the same
// seed and inflow history give the same vortices.

#include "simulator/fluid/artificial_vortices.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace viscera;
using namespace viscera::sim::fluid;

TEST(ArtificialVortices, a_vortex_is_lamb_oseen) {
  Vortex vortex;
  vortex.centre = core::Vec3(0.01, 0.0, 0.0);
  vortex.axis = core::Vec3(0.0, 0.6, 0.8);
  const double gamma = 1e-3, rc = 0.002;
  const core::Vec3 across = core::Vec3(1.0, 0.0, 0.0);  // ⊥ the axis
  double fastest = 0.0, at = 0.0;
  for (int s = 1; s <= 400; ++s) {
    const double r = s * 2.5e-5;
    const core::Vec3 v = lamb_oseen_velocity(vortex, gamma, rc, vortex.centre + r * across);
    const double expected =
        gamma / (2.0 * std::numbers::pi * r) * (1.0 - std::exp(-r * r / (rc * rc)));
    EXPECT_NEAR(v.norm(), expected, 1e-12);
    EXPECT_NEAR(v.dot(across), 0.0, 1e-15);       // tangential
    EXPECT_NEAR(v.dot(vortex.axis), 0.0, 1e-15);  // no flow along the axis
    if (v.norm() > fastest) fastest = v.norm(), at = r;
  }
  EXPECT_NEAR(at / rc, 1.1209, 0.02);  // the Lamb–Oseen maximum
  // Divergence-free: central differences at an off-axis point.
  const core::Vec3 p = vortex.centre + core::Vec3(0.0013, -0.0007, 0.0009);
  const double h = 1e-6;
  double divergence = 0.0;
  for (int a = 0; a < 3; ++a) {
    const core::Vec3 e = h * core::Vec3::Unit(a);
    divergence += (lamb_oseen_velocity(vortex, gamma, rc, p + e)[a] -
                   lamb_oseen_velocity(vortex, gamma, rc, p - e)[a]) /
                  (2.0 * h);
  }
  EXPECT_LT(std::abs(divergence), 1e-6 * fastest / h);
}

TEST(ArtificialVortices, appear_with_the_inflow_fade_and_repeat_for_a_seed) {
  FlowGrid grid(20, 20, 20, 0.001);
  VortexSettings settings;
  ArtificialVortices a(settings, 3), b(settings, 3);
  a.advance(grid, 0.5 * settings.threshold_flow, 0.01);
  EXPECT_TRUE(a.vortices().empty());
  a.advance(grid, settings.threshold_flow + 3.5 * settings.flow_per_vortex, 0.01);
  EXPECT_EQ(a.vortices().size(), 4u);
  a.advance(grid, 100.0 * settings.threshold_flow, 0.01);
  EXPECT_EQ(a.vortices().size(), static_cast<std::size_t>(settings.max_count));
  EXPECT_GT(a.velocity(core::Vec3(0.01, 0.01, 0.01)).norm(), 0.0);
  // Off: they fade and are gone after their lifetime.
  const int steps = static_cast<int>(settings.lifetime / 0.01) + 1;
  for (int s = 0; s < steps; ++s)
    a.advance(grid, 0.0, 0.01);
  EXPECT_TRUE(a.vortices().empty());
  // The same history with the same seed gives the same vortices.
  b.advance(grid, 0.5 * settings.threshold_flow, 0.01);
  b.advance(grid, settings.threshold_flow + 3.5 * settings.flow_per_vortex, 0.01);
  ArtificialVortices c(settings, 3);
  c.advance(grid, 0.5 * settings.threshold_flow, 0.01);
  c.advance(grid, settings.threshold_flow + 3.5 * settings.flow_per_vortex, 0.01);
  ASSERT_EQ(b.vortices().size(), c.vortices().size());
  for (std::size_t v = 0; v < b.vortices().size(); ++v) {
    EXPECT_EQ(b.vortices()[v].centre, c.vortices()[v].centre);
    EXPECT_EQ(b.vortices()[v].axis, c.vortices()[v].axis);
  }
}
