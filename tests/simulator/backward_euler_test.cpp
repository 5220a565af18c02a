// Backward Euler against the explicit reference: the same quasi-static sag (clamped beam, ball),
// no sub-steps, and energy that never grows without input.
#include "simulator/dynamics/backward_euler.h"

#include <gtest/gtest.h>

#include "core/meshing/tet_mesher.h"
#include "core/primitives/icosphere.h"
#include "simulator/world/world.h"
#include "tests/simulator/sim_fixtures.h"

namespace viscera::sim {
namespace {

/// A 10 × 2 × 2 cm beam clamped at x = 0, under gravity, damped so it settles.
core::Scenario clamped_beam() {
  core::Scenario scenario;
  scenario.materials["soft"] = viscera::testing::soft_test_material(2000.0);
  scenario.materials["soft"].distance_stiffness = 2.0e5;
  scenario.materials["soft"].volume_stiffness = 2.0e5;
  core::SceneObject beam = viscera::testing::held_block("beam", 10, 2, 2, 0.01);
  for (std::size_t n = 0; n < beam.body.nodes.size(); ++n)
    beam.body.fixed[n] = beam.body.nodes[n].x() < 1e-9 ? 1 : 0;
  scenario.objects.push_back(beam);
  scenario.session.gravity = core::Vec3(0.0, 0.0, -9.81);
  return scenario;
}

/// A ball of 3 cm radius held at its lowest nodes, under gravity.
core::Scenario held_ball() {
  core::Scenario scenario;
  scenario.materials["soft"] = viscera::testing::soft_test_material(400.0);
  core::SceneObject ball;
  ball.id = "ball";
  ball.material = "soft";
  ball.body_kind = core::BodyKind::TetMesh;
  ball.body = core::mesh_closed_surface(core::make_icosphere(0.03, 2));
  ball.body.fixed.assign(ball.body.nodes.size(), 0);
  for (std::size_t n = 0; n < ball.body.nodes.size(); ++n)
    ball.body.fixed[n] = ball.body.nodes[n].z() < -0.025 ? 1 : 0;
  scenario.objects.push_back(ball);
  scenario.session.gravity = core::Vec3(0.0, 0.0, -9.81);
  return scenario;
}

/// Drop in m of the centre of mass after `seconds`, and the kinetic energy left.
std::pair<double, double> settle(const core::Scenario& scenario, IntegratorKind kind,
                                 double seconds) {
  World world(scenario, kind);
  const double start = world.bodies()[0].centre_of_mass().z();
  const int steps = static_cast<int>(seconds / world.time_step() + 0.5);
  for (int s = 0; s < steps; ++s)
    world.step();
  return {start - world.bodies()[0].centre_of_mass().z(), world.energies().kinetic};
}

TEST(BackwardEuler, the_clamped_beam_sags_as_far_as_with_the_explicit_reference) {
  const core::Scenario beam = clamped_beam();
  const auto [implicit, implicit_kinetic] = settle(beam, IntegratorKind::BackwardEuler, 3.0);
  const auto [explicit_, explicit_kinetic] = settle(beam, IntegratorKind::ExplicitVerlet, 3.0);
  ASSERT_GT(explicit_, 1e-4);
  EXPECT_NEAR(implicit, explicit_, 0.01 * explicit_);
  EXPECT_LT(implicit_kinetic, 1e-5);  // settled: mJ of sag energy, µJ of motion
  EXPECT_LT(explicit_kinetic, 1e-5);
}

TEST(BackwardEuler, the_ball_sags_as_far_as_with_the_explicit_reference) {
  const core::Scenario ball = held_ball();
  const auto [implicit, implicit_kinetic] = settle(ball, IntegratorKind::BackwardEuler, 2.0);
  const auto [explicit_, explicit_kinetic] = settle(ball, IntegratorKind::ExplicitVerlet, 2.0);
  ASSERT_GT(explicit_, 1e-5);
  EXPECT_NEAR(implicit, explicit_, 0.01 * explicit_);
  EXPECT_LT(implicit_kinetic, 1e-5);  // settled: mJ of sag energy, µJ of motion
  EXPECT_LT(explicit_kinetic, 1e-5);
}

TEST(BackwardEuler, takes_no_substeps_and_never_gains_energy) {
  core::Scenario stiff = clamped_beam();
  stiff.materials["soft"].distance_stiffness = 3.0e6;
  stiff.materials["soft"].volume_stiffness = 3.0e6;
  stiff.materials["soft"].distance_damping = 1.0;
  World world(stiff, IntegratorKind::BackwardEuler);
  EXPECT_EQ(world.substeps(), 1);
  EXPECT_EQ(world.integrator().name(), "backward-euler");
  // A jiggled start excites every mode; the total energy may only fall.
  auto x = world.bodies()[0].positions();
  std::vector<Vec3> moved(x.begin(), x.end());
  viscera::testing::jiggle(moved, 5e-4, 3);
  for (std::size_t n = 0; n < x.size(); ++n)
    if (world.bodies()[0].inverse_masses()[n] > 0.0) x[n] = moved[n];
  double previous = world.energies().total();
  for (int s = 0; s < 300; ++s) {
    world.step();
    const double energy = world.energies().total();
    ASSERT_LE(energy, previous + 1e-12 * std::abs(previous)) << "step " << s + 1;
    previous = energy;
  }
}

TEST(BackwardEuler, is_the_default_for_teschner_bodies) {
  World world(clamped_beam());
  EXPECT_EQ(world.integrator().name(), "backward-euler");
  World explicit_world(clamped_beam(), IntegratorKind::ExplicitVerlet);
  EXPECT_EQ(explicit_world.integrator().name(), "explicit-verlet");
}

}  // namespace
}  // namespace viscera::sim
