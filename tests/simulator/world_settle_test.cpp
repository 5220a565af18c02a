#include <gtest/gtest.h>

#include <algorithm>

#include "simulator/world/world.h"
#include "tests/simulator/sim_fixtures.h"

namespace viscera::sim {
namespace {

/// A 6 × 1 × 1 cm soft cantilever held at its x = 0 face (or free), under gravity, 1 ms steps.
core::Scenario cantilever(bool held = true) {
  core::Scenario scenario;
  scenario.materials["soft"] = viscera::testing::soft_test_material();
  core::SceneObject beam = viscera::testing::held_block("beam", 6, 1, 1, 0.01);
  for (std::size_t n = 0; n < beam.body.nodes.size(); ++n)
    beam.body.fixed[n] = held && beam.body.nodes[n].x() < 1e-9 ? 1 : 0;
  scenario.objects.push_back(beam);
  scenario.session.gravity = core::Vec3(0.0, 0.0, -9.81);
  scenario.session.time_step = 1e-3;
  return scenario;
}

/// The largest distance any node travels over `steps` steps of the world.
double largest_travel(World& world, int steps) {
  const std::vector<core::Vec3> before = world.state().positions;
  for (int s = 0; s < steps; ++s)
    world.step();
  double travel = 0.0;
  for (std::size_t i = 0; i < before.size(); ++i)
    travel = std::max(travel, (world.state().positions[i] - before[i]).norm());
  return travel;
}

TEST(WorldSettle, a_held_beam_starts_at_its_sag_and_stays_there) {
  World settled(cantilever());
  const World::Settling s = settled.settle();
  EXPECT_TRUE(s.at_rest);
  EXPECT_GE(s.steps, 2);
  EXPECT_LT(s.last_move, 1e-7);
  EXPECT_EQ(settled.time(), 0.0);
  EXPECT_EQ(settled.state().time, 0.0);
  double tip_sag = 0.0;
  for (std::size_t i = 0; i < settled.state().node_count(); ++i) {
    EXPECT_EQ(settled.state().velocities[i], core::Vec3::Zero());
    tip_sag =
        std::max(tip_sag, settled.state().rest_positions[i].z() - settled.state().positions[i].z());
  }
  EXPECT_GT(tip_sag, 1e-4);  // the free end hangs by a measurable amount
  // From the settled shape, 0.2 s of dynamics moves nothing by more than a micrometre; from the
  // authored (straight) shape, the beam swings down by a good part of its sag.
  EXPECT_LT(largest_travel(settled, 200), 1e-6);
  World authored(cantilever());
  EXPECT_GT(largest_travel(authored, 200), 0.3 * tip_sag);
}

TEST(WorldSettle, a_world_settled_at_rest_with_sleeping_on_starts_asleep_and_stays_at_its_sag) {
  World sleeping(cantilever());
  sleeping.set_sleep_threshold(1e-7);
  ASSERT_TRUE(sleeping.settle().at_rest);
  EXPECT_TRUE(sleeping.asleep());
  // Asleep, nothing moves; the same settle with sleeping off starts awake and, stepped, stays
  // within a micrometre of the same shape.
  const std::vector<core::Vec3> settled = sleeping.state().positions;
  EXPECT_EQ(largest_travel(sleeping, 50), 0.0);
  World awake(cantilever());
  ASSERT_TRUE(awake.settle().at_rest);
  EXPECT_FALSE(awake.asleep());
  EXPECT_EQ(awake.state().positions, settled);  // the same descent, bit for bit
  EXPECT_LT(largest_travel(awake, 200), 1e-6);
}

TEST(WorldSettle, a_free_body_is_not_settled) {
  World world(cantilever(false));
  const std::vector<core::Vec3> before = world.state().positions;
  const World::Settling s = world.settle();
  EXPECT_EQ(s.steps, 0);
  EXPECT_FALSE(s.at_rest);
  EXPECT_EQ(world.state().positions, before);
}

}  // namespace
}  // namespace viscera::sim
