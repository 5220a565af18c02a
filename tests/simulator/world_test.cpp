#include "simulator/world/world.h"

#include <gtest/gtest.h>

#include <limits>

#include "core/error.h"
#include "tests/simulator/sim_fixtures.h"

namespace viscera::sim {
namespace {

/// A 2 × 2 × 3 cm soft block on its fixed base, under gravity, at a step of `time_step` s.
core::Scenario small_block(double time_step = 1e-3) {
  core::Scenario scenario;
  scenario.materials["soft"] = viscera::testing::soft_test_material();
  scenario.objects.push_back(viscera::testing::held_block("block", 2, 2, 3, 0.01));
  scenario.session.gravity = core::Vec3(0.0, 0.0, -9.81);
  scenario.session.time_step = time_step;
  return scenario;
}

std::string hash_after(double simulated_time, double time_step) {
  World world(small_block(time_step));
  const auto steps = static_cast<int>(std::lround(simulated_time / time_step));
  for (int s = 0; s < steps; ++s)
    world.step();
  return world.state_hash();
}

TEST(World, a_different_time_step_gives_a_different_hash) {
  EXPECT_EQ(hash_after(0.1, 1e-3), hash_after(0.1, 1e-3));
  // Steps whose sub-steps differ in length: with a stable step above 0.3 ms, 0.3 ms is one
  // sub-step and 1 ms splits into 1 ms / n ≠ 0.3 ms. (1 ms and 0.5 ms may both run 0.5 ms
  // sub-steps, which rightly gives equal states.)
  const World world(small_block(1e-3));
  ASSERT_GT(world.stable_step(), 3e-4);
  EXPECT_NE(hash_after(0.1, 1e-3), hash_after(0.099, 3e-4));
}

TEST(World, the_hash_covers_velocities) {
  World a(small_block()), b(small_block());
  b.bodies()[0].velocities()[7].x() += 1e-12;  // a velocity change only
  EXPECT_NE(a.state_hash(), b.state_hash());
}

TEST(World, energies_at_rest_are_zero_and_follow_a_rigid_motion) {
  World world(small_block());
  EXPECT_EQ(world.energies().total(), 0.0);
  // Move every node 1 mm down and give it 0.2 m/s along x: kinetic ½ M v², gravitational
  // −M g·d relative to rest, no elastic energy.
  BodyView& body = world.bodies()[0];
  const core::Vec3 drop(0.0, 0.0, -1e-3), velocity(0.2, 0.0, 0.0);
  double mass = 0.0;
  for (std::size_t i = 0; i < body.node_count(); ++i) {
    body.positions()[i] = body.rest_positions()[i] + drop;
    body.velocities()[i] = velocity;
    mass += body.masses()[i];
  }
  const BodyEnergies e = world.energies();
  EXPECT_NEAR(e.kinetic, 0.5 * mass * velocity.squaredNorm(), 1e-12 * mass);
  EXPECT_NEAR(e.gravitational, -mass * world.gravity().dot(drop), 1e-12 * mass);
  EXPECT_NEAR(e.elastic, 0.0, 1e-18);
}

TEST(World, non_finite_positions_raise_an_error_naming_the_body_and_step) {
  World world(small_block());
  for (int s = 0; s < 3; ++s)
    world.step();
  world.bodies()[0].positions()[20].y() = std::numeric_limits<double>::quiet_NaN();
  try {
    world.step();
    FAIL() << "a NaN position went unnoticed";
  } catch (const core::Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("block"), std::string::npos) << message;
    EXPECT_NE(message.find("step 4"), std::string::npos) << message;
  }
}

/// Mirrors the top layer of the block through its base and holds it there: the tets up there
/// stay everted.
void evert_top_layer(World& world) {
  auto& state = world.state();
  for (std::size_t n = 0; n < state.node_count(); ++n)
    if (state.positions[n].z() > 0.02) {
      state.positions[n].z() = -state.positions[n].z();
      state.inverse_masses[n] = 0.0;
    }
}

TEST(World, an_everted_tet_is_an_error_by_default_naming_body_node_and_step) {
  World world(small_block());
  world.step();
  evert_top_layer(world);
  EXPECT_GT(world.everted_tets(), 0);
  try {
    world.step();
    FAIL() << "an everted tet went unnoticed";
  } catch (const core::Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("block"), std::string::npos) << message;
    EXPECT_NE(message.find("inside out"), std::string::npos) << message;
    EXPECT_NE(message.find("step 2"), std::string::npos) << message;
    EXPECT_NE(message.find("node "), std::string::npos) << message;
  }
}

TEST(World, everted_tets_are_only_counted_when_inversion_errors_are_off) {
  World world(small_block());
  world.set_inversion_errors(false);
  world.step();
  evert_top_layer(world);
  const int everted = world.everted_tets();
  EXPECT_GT(everted, 0);
  EXPECT_NO_THROW(world.step());
  EXPECT_GT(world.everted_tets(), 0);
}

}  // namespace
}  // namespace viscera::sim
