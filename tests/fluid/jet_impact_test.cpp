// Eq. 4 and 5 of seed 001 §4.3 (simulator/fluid/jet_impact.h): the rebound keeps (1 − µ) of the
// slide and reverses ε of the normal speed; the impact force points along the incoming drop
// and grows with the kinetic energy it lost.

#include "simulator/fluid/jet_impact.h"

#include <gtest/gtest.h>

using namespace viscera;
using namespace viscera::sim::fluid;

TEST(JetImpact, rebound_keeps_the_slide_less_friction_and_reverses_the_normal_by_elasticity) {
  const core::Vec3 v(3.0, 0.0, -4.0);  // m/s onto the plane z = 0
  const core::Vec3 n(0.0, 0.0, 1.0);
  const core::Vec3 out = rebound_velocity(v, n, 0.2, 0.3);
  EXPECT_NEAR(out.x(), 0.7 * 3.0, 1e-15);  // (1 − µ) v_T
  EXPECT_NEAR(out.y(), 0.0, 1e-15);
  EXPECT_NEAR(out.z(), 0.2 * 4.0, 1e-15);  // −ε v_N, away from the surface
  // The normal's orientation does not matter.
  EXPECT_NEAR((rebound_velocity(v, -n, 0.2, 0.3) - out).norm(), 0.0, 1e-15);
  // ε = 1, µ = 0: a mirror bounce that keeps the speed.
  const core::Vec3 mirror = rebound_velocity(v, n, 1.0, 0.0);
  EXPECT_NEAR((mirror - core::Vec3(3.0, 0.0, 4.0)).norm(), 0.0, 1e-15);
  // On a tilted plane the tangential and normal parts are those of that plane.
  const core::Vec3 tilted = core::Vec3(1.0, 0.0, 1.0).normalized();
  const core::Vec3 w(0.0, 0.0, -2.0);
  const core::Vec3 r = rebound_velocity(w, tilted, 0.5, 0.5);
  const core::Vec3 w_n = w.dot(tilted) * tilted, w_t = w - w_n;
  EXPECT_NEAR(r.dot(tilted), -0.5 * w.dot(tilted), 1e-15);
  EXPECT_NEAR((r - r.dot(tilted) * tilted - 0.5 * w_t).norm(), 0.0, 1e-15);
}

TEST(JetImpact, force_points_along_the_incoming_drop_and_scales_with_the_energy_lost) {
  const double m = 1e-5, k = 500.0;  // a 0.01 ml drop, stopped over 1 mm
  const core::Vec3 v_old(0.0, 0.0, -0.8);
  const core::Vec3 v_new(0.0, 0.0, 0.16);  // ε = 0.2
  const core::Vec3 f = impact_force(m, k, v_old, v_new);
  // m k (|v_old|² − |v_new|²) = 1e-5 · 500 · (0.64 − 0.0256) N, along −z.
  EXPECT_NEAR(f.z(), -1e-5 * 500.0 * 0.6144, 1e-15);
  EXPECT_EQ(f.x(), 0.0);
  EXPECT_EQ(f.y(), 0.0);
  // Oblique: the force is parallel to v_old, not to the normal.
  const core::Vec3 oblique(0.6, 0.0, -0.8);
  const core::Vec3 g = impact_force(m, k, oblique, core::Vec3(0.42, 0.0, 0.16));
  EXPECT_NEAR(g.normalized().dot(oblique.normalized()), 1.0, 1e-15);
  EXPECT_NEAR(g.norm(), m * k * (1.0 - (0.42 * 0.42 + 0.16 * 0.16)), 1e-15);
  // Work–energy: F · d with d = 1/(2k) is the kinetic energy lost.
  EXPECT_NEAR(f.norm() / (2.0 * k), 0.5 * m * (0.64 - 0.0256), 1e-15);
  // No push without a loss, and none from a drop at rest.
  EXPECT_EQ(impact_force(m, k, v_old, core::Vec3(0.0, 0.0, 0.9)), core::Vec3::Zero());
  EXPECT_EQ(impact_force(m, k, core::Vec3::Zero(), core::Vec3::Zero()), core::Vec3::Zero());
}
