#include "simulator/dynamics/connection_spring_term.h"

#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "simulator/world/world.h"
#include "tests/simulator/sim_fixtures.h"
#include "tests/support/tet_block.h"

namespace viscera::sim {
namespace {

/// Two 2 × 2 × 2 cm soft blocks side by side with a 1 cm gap along x: "left" with its base
/// fixed, "right" free. With `connected`, the facing nodes of the two blocks (x = 2 cm and
/// x = 3 cm, same y and z) are joined by springs of `stiffness` N/m.
core::Scenario two_blocks(bool connected, double stiffness = 200.0) {
  core::Scenario scenario;
  scenario.materials["soft"] = viscera::testing::soft_test_material();
  const core::SceneObject left = viscera::testing::held_block("left", 2, 2, 2, 0.01);
  core::SceneObject right = left;
  right.id = "right";
  right.body.fixed.clear();
  for (auto& node : right.body.nodes)
    node.x() += 0.03;
  scenario.objects = {left, right};
  if (connected) {
    core::Connection connection;
    connection.id = "left-right";
    connection.object_a = "left";
    connection.object_b = "right";
    connection.stiffness = stiffness;
    for (std::size_t a = 0; a < left.body.nodes.size(); ++a) {
      if (left.body.nodes[a].x() < 0.02 - 1e-9) continue;
      for (std::size_t b = 0; b < right.body.nodes.size(); ++b) {
        if ((right.body.nodes[b] - left.body.nodes[a] - core::Vec3(0.01, 0, 0)).norm() < 1e-9)
          connection.node_pairs.push_back({static_cast<int>(a), static_cast<int>(b)});
      }
    }
    scenario.connections.push_back(connection);
  }
  scenario.session.gravity = core::Vec3(0.0, 0.0, -9.81);
  scenario.session.time_step = 1e-3;
  return scenario;
}

const ConnectionSpringTerm& connections(const World& world) {
  for (const auto& term : world.terms())
    if (const auto* springs = dynamic_cast<const ConnectionSpringTerm*>(term.get()))
      return *springs;
  throw std::logic_error("the world has no connection springs");
}

/// Connection forces alone, per body and node.
std::vector<std::vector<core::Vec3>> connection_forces(const World& world) {
  std::vector<core::Vec3> f(world.state().node_count(), core::Vec3::Zero());
  connections(world).add_forces(world.state().positions, world.state().velocities, f);
  std::vector<std::vector<core::Vec3>> per_body;
  for (const auto& body : world.bodies())
    per_body.emplace_back(f.begin() + body.first_node(),
                          f.begin() + body.first_node() + static_cast<long>(body.node_count()));
  return per_body;
}

TEST(ConnectionSprings, join_the_facing_nodes_with_their_rest_distance) {
  World world(two_blocks(true));
  ASSERT_EQ(connections(world).springs().size(), 9u);  // a 3 × 3 grid of facing nodes
  for (const auto& spring : connections(world).springs()) {
    EXPECT_EQ(spring.body_a, 0);
    EXPECT_EQ(spring.body_b, 1);
    EXPECT_NEAR(spring.rest_length, 0.01, 1e-12);
  }
  for (const auto& spring : connections(world).springs())
    EXPECT_DOUBLE_EQ(spring.stiffness, 200.0);
}

TEST(ConnectionSprings, forces_cancel_and_are_the_gradient_of_the_energy) {
  World world(two_blocks(true, 350.0));
  viscera::testing::jiggle(world.state().positions, 2e-3, 7);
  const auto forces = connection_forces(world);
  core::Vec3 total = core::Vec3::Zero();
  for (const auto& body_forces : forces)
    for (const auto& f : body_forces)
      total += f;
  double largest = 0.0;
  for (const auto& body_forces : forces)
    for (const auto& f : body_forces)
      largest = std::max(largest, f.norm());
  ASSERT_GT(largest, 1e-3);
  EXPECT_LT(total.norm(), 1e-10);  // rounding of the body forces they were added to

  // Central differences of the spring energy against the force on every connected node.
  const double eps = 1e-7;
  auto& bodies = world.bodies();
  const auto energy = [&] { return connections(world).energy(world.state().positions); };
  for (const auto& spring : connections(world).springs()) {
    for (int axis = 0; axis < 3; ++axis) {
      core::Vec3& x = bodies[static_cast<std::size_t>(spring.body_b)].positions()[spring.node_b];
      const double saved = x[axis];
      x[axis] = saved + eps;
      const double plus = energy();
      x[axis] = saved - eps;
      const double minus = energy();
      x[axis] = saved;
      const double expected = -(plus - minus) / (2 * eps);
      EXPECT_NEAR(forces[static_cast<std::size_t>(spring.body_b)][spring.node_b][axis], expected,
                  1e-6 + 1e-5 * std::abs(expected));
    }
  }
}

/// Height drop in m of the right block's centre of mass after `seconds` of simulated time.
double drop_after(World& world, double seconds) {
  const double start = world.bodies()[1].centre_of_mass().z();
  const int steps = static_cast<int>(seconds / world.time_step() + 0.5);
  for (int s = 0; s < steps; ++s)
    world.step();
  return start - world.bodies()[1].centre_of_mass().z();
}

TEST(ConnectionSprings, a_connected_block_hangs_where_a_free_one_falls) {
  World free_world(two_blocks(false));
  World connected_world(two_blocks(true, 2000.0));
  const double free_drop = drop_after(free_world, 0.3);
  const double connected_drop = drop_after(connected_world, 0.3);
  EXPECT_NEAR(free_drop, 0.5 * 9.81 * 0.3 * 0.3, 0.02);  // falls freely: g t² / 2 = 0.44 m
  EXPECT_GT(connected_drop, 0.0);
  // Held: it sags on the springs and the soft blocks bend, a twentieth of the free fall at most.
  EXPECT_LT(connected_drop, 0.05 * free_drop);
  const BodyEnergies energies = connected_world.energies();
  EXPECT_TRUE(std::isfinite(energies.total()));
  EXPECT_GT(energies.elastic, 0.0);
}

TEST(ConnectionSprings, stiff_connections_shorten_the_step_and_stay_finite) {
  World soft(two_blocks(true, 200.0), IntegratorKind::ExplicitVerlet);
  World stiff(two_blocks(true, 2.0e4), IntegratorKind::ExplicitVerlet);
  ASSERT_GT(stiff.substeps(), soft.substeps());
  ASSERT_LT(stiff.substeps(), 200) << "soft: " << soft.substeps();
  // Damped and stable: the total energy (kinetic + elastic incl. springs + gravitational) never
  // grows while the block swings on its connection.
  double previous = stiff.energies().total();
  for (int interval = 0; interval < 6; ++interval) {
    drop_after(stiff, 0.05);
    for (const auto& p : stiff.bodies()[1].positions())
      ASSERT_TRUE(p.allFinite());
    const double energy = stiff.energies().total();
    EXPECT_LE(energy, previous + 1e-7) << "after " << 0.05 * (interval + 1) << " s";
    previous = energy;
  }
  EXPECT_LT(previous, 0.0);  // it has settled below its start, held by the springs
}

TEST(ConnectionSprings, refuse_an_object_without_a_body_naming_the_connection) {
  core::Scenario scenario = two_blocks(true);
  scenario.connections[0].object_b = "ovary";
  try {
    World world(scenario);
    FAIL() << "a connection to a missing object was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("\"ovary\" has no simulated body"), std::string::npos)
        << e.what();
    EXPECT_EQ(e.location().json_pointer, "/scenario/connections/0/object_b");
  }
}

TEST(ConnectionSprings, refuse_a_node_the_body_does_not_have) {
  core::Scenario scenario = two_blocks(true);
  scenario.connections[0].node_pairs[4][1] = 27;  // a 2 × 2 × 2 block has 27 nodes: 0…26
  try {
    World world(scenario);
    FAIL() << "an out-of-range node was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("node 27 is not a node of body \"right\""),
              std::string::npos)
        << e.what();
    EXPECT_EQ(e.location().json_pointer, "/scenario/connections/0/node_pairs/4/1");
  }
}

}  // namespace
}  // namespace viscera::sim
