#include "simulator/physics/kismo_mass_spring.h"

#include <gtest/gtest.h>

#include <numbers>

#include "core/random.h"

namespace viscera::sim {
namespace {

TEST(KismoMassSpring, cubic_spring_forces_are_the_negative_energy_gradient) {
  CubicSprings springs{{{0, 1}, {1, 2}, {0, 2}},
                       {0.01, 0.012, 0.015},
                       {{{2.0, 30.0, 400.0}}, {{1.0, 0.0, 50.0}}, {{3.0, -5.0, 0.0}}},
                       {}};
  std::vector<core::Vec3> x = {{0, 0, 0}, {0.0125, 0.001, 0.0}, {0.003, 0.009, 0.002}};
  std::vector<core::Vec3> f(3, core::Vec3::Zero());
  add_cubic_spring_forces(x, springs, f);
  const double h = 1e-8;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      auto plus = x, minus = x;
      plus[i][c] += h;
      minus[i][c] -= h;
      std::vector<core::Vec3> scratch(3, core::Vec3::Zero());
      const double gradient = (add_cubic_spring_forces(plus, springs, scratch) -
                               add_cubic_spring_forces(minus, springs, scratch)) /
                              (2 * h);
      EXPECT_NEAR(f[i][c], -gradient, 1e-5 * (1.0 + std::abs(gradient))) << i << " " << c;
    }
  EXPECT_LT((f[0] + f[1] + f[2]).norm(), 1e-12);  // internal forces: no net force
}

TEST(KismoMassSpring, the_one_pass_forces_equal_the_spring_forces_plus_the_damping_forces) {
  // Stretched, compressed and sheared springs with damping elements, knots moving apart and
  // together: one pass gives what the two passes give, to rounding, and the same energy.
  CubicSprings springs{
      {{0, 1}, {1, 2}, {0, 2}, {2, 3}},
      {0.01, 0.012, 0.015, 0.008},
      {{{2.0, 30.0, 400.0}}, {{1.0, 0.0, 50.0}}, {{3.0, -5.0, 0.0}}, {{4.0, 1.0, 9.0}}},
      {0.02, 0.5, 0.0, 3.0}};
  const std::vector<core::Vec3> x = {
      {0, 0, 0}, {0.0125, 0.001, 0.0}, {0.003, 0.009, 0.002}, {0.004, 0.012, 0.0075}};
  const std::vector<core::Vec3> v = {
      {0.1, -0.2, 0.05}, {-0.3, 0.0, 0.2}, {0.0, 0.4, -0.1}, {1, 1, 1}};
  std::vector<core::Vec3> two(4, core::Vec3::Zero()), one(4, core::Vec3::Zero());
  add_spring_damping_forces(x, v, springs, two);
  const double energy_two = add_cubic_spring_forces(x, springs, two);
  const double energy_one = add_damped_cubic_spring_forces(x, v, springs, one);
  EXPECT_DOUBLE_EQ(energy_one, energy_two);
  EXPECT_DOUBLE_EQ(cubic_spring_energy(x, springs), energy_two);
  for (std::size_t i = 0; i < x.size(); ++i)
    EXPECT_LT((one[i] - two[i]).norm(), 1e-12 * two[i].norm()) << i;
  // The damping is in it: without it the forces differ by far more than rounding.
  CubicSprings undamped = springs;
  undamped.damping.clear();
  std::vector<core::Vec3> bare(4, core::Vec3::Zero());
  EXPECT_DOUBLE_EQ(add_damped_cubic_spring_forces(x, v, undamped, bare), energy_two);
  EXPECT_GT((bare[3] - one[3]).norm(), 1e-3 * one[3].norm());
}

TEST(KismoMassSpring, hanging_knot_comes_to_rest_at_the_linear_extension_mg_over_k) {
  // A 10 g knot hanging from a held knot on a linear 5 N spring of 2 cm rest length:
  // k = k1 / l0 = 250 N/m, so the static extension is m g / k = 0.392 mm.
  CubicSprings spring{{{0, 1}}, {0.02}, {{{5.0, 0.0, 0.0}}}, {}};
  std::vector<core::Vec3> x = {{0, 0, 0}, {0, 0, -0.02}}, v(2, core::Vec3::Zero());
  KnotParameters knots{{1.0, 0.01}, {0.0, 0.2}, {{{0, 0, 0}}, {{1, 1, 1}}}};
  const core::Vec3 g(0, 0, -9.81);
  for (int s = 0; s < 20000; ++s) {
    std::vector<core::Vec3> f(2, core::Vec3::Zero());
    add_cubic_spring_forces(x, spring, f);
    kismo_step(x, v, f, knots, g, 1e-4);
  }
  EXPECT_EQ(x[0], core::Vec3::Zero());  // the bounding matrix holds knot 0
  EXPECT_NEAR(x[1].z(), -0.02 - 0.01 * 9.81 / 250.0, 1e-7);
  EXPECT_LT(v[1].norm(), 1e-6);
}

TEST(KismoMassSpring, undamped_linear_spring_oscillates_with_the_analytic_period) {
  // m = 0.01 kg on k = 250 N/m: ω = sqrt(k/m) = 158.1 rad/s, T = 39.74 ms.
  CubicSprings spring{{{0, 1}}, {0.02}, {{{5.0, 0.0, 0.0}}}, {}};
  std::vector<core::Vec3> x = {{0, 0, 0}, {0.021, 0, 0}}, v(2, core::Vec3::Zero());
  KnotParameters knots{{1.0, 0.01}, {0.0, 0.0}, {{{0, 0, 0}}, {{1, 1, 1}}}};
  const double h = 1e-5;
  double last_crossing = -1.0, period = 0.0;
  double previous = x[1].x() - 0.02;
  for (int s = 1; s < 20000; ++s) {
    std::vector<core::Vec3> f(2, core::Vec3::Zero());
    add_cubic_spring_forces(x, spring, f);
    kismo_step(x, v, f, knots, core::Vec3::Zero(), h);
    const double now = x[1].x() - 0.02;
    if (previous > 0.0 && now <= 0.0) {
      if (last_crossing > 0.0) period = s * h - last_crossing;
      last_crossing = s * h;
    }
    previous = now;
  }
  EXPECT_NEAR(period, 2.0 * std::numbers::pi * std::sqrt(0.01 / 250.0), 2e-4);
}

TEST(KismoMassSpring, bounding_matrix_can_hold_single_axes) {
  CubicSprings none;
  std::vector<core::Vec3> x = {{0, 0, 0}}, v(1, core::Vec3::Zero());
  KnotParameters knots{{0.1}, {0.0}, {{{1, 1, 0}}}};  // slides in x and y, held in z
  const std::vector<core::Vec3> f = {{0.1, 0.2, 5.0}};
  kismo_step(x, v, f, knots, core::Vec3(0, 0, -9.81), 0.01);
  EXPECT_GT(x[0].x(), 0.0);
  EXPECT_GT(x[0].y(), 0.0);
  EXPECT_EQ(x[0].z(), 0.0);
}

TEST(KismoMassSpring, coefficients_scale_the_stress_cubic_by_the_cross_section) {
  const auto k = spring_coefficients_from_cubic({8000.0, 1000.0, 500.0}, 1e-4);
  EXPECT_DOUBLE_EQ(k[0], 0.8);
  EXPECT_DOUBLE_EQ(k[1], 0.1);
  EXPECT_DOUBLE_EQ(k[2], 0.05);
}

}  // namespace
}  // namespace viscera::sim
