// World::topology_changed: re-meshing a body rebuilds every cache and the body still steps.
#include <gtest/gtest.h>

#include "simulator/world/world.h"
#include "tests/simulator/sim_fixtures.h"

namespace viscera::sim {
namespace {

core::Scenario hanging_block() {
  core::Scenario scenario;
  scenario.materials["soft"] = viscera::testing::soft_test_material(200.0);
  scenario.objects.push_back(viscera::testing::held_block("block", 2, 2, 3, 0.01));
  scenario.session.gravity = Vec3(0.0, 0.0, -9.81);
  return scenario;
}

/// Tet `t` of the body split in four at a new node at its centroid.
BodyTopology split_tet(const BodyView& body, int t) {
  BodyTopology topology;
  topology.rest_mesh.nodes.assign(body.rest_positions().begin(), body.rest_positions().end());
  topology.positions.assign(body.positions().begin(), body.positions().end());
  for (std::size_t n = 0; n < topology.positions.size(); ++n) {
    NodeOrigin o;
    o.node = {static_cast<int>(n), -1, -1, -1};
    o.weight = {1.0, 0.0, 0.0, 0.0};
    topology.origin.push_back(o);
  }
  const core::Tetrahedron tet = body.tets()[static_cast<std::size_t>(t)];
  const int centre = static_cast<int>(topology.rest_mesh.nodes.size());
  Vec3 rest = Vec3::Zero(), now = Vec3::Zero();
  for (const int n : tet) {
    rest += body.rest_positions()[static_cast<std::size_t>(n)] / 4.0;
    now += body.positions()[static_cast<std::size_t>(n)] / 4.0;
  }
  topology.rest_mesh.nodes.push_back(rest);
  topology.positions.push_back(now);
  topology.origin.push_back({{tet[0], tet[1], tet[2], tet[3]}, {0.25, 0.25, 0.25, 0.25}});
  for (std::size_t k = 0; k < body.tets().size(); ++k) {
    if (static_cast<int>(k) == t) continue;
    topology.rest_mesh.tets.push_back(body.tets()[k]);
    topology.tet_parent.push_back(static_cast<int>(k));
  }
  // Replacing one corner by the centroid keeps each new tet's orientation.
  for (int corner = 0; corner < 4; ++corner) {
    core::Tetrahedron child = tet;
    child[static_cast<std::size_t>(corner)] = centre;
    topology.rest_mesh.tets.push_back(child);
    topology.tet_parent.push_back(t);
  }
  topology.rest_mesh.fixed.assign(topology.rest_mesh.nodes.size(), 0);
  for (std::size_t n = 0; n < topology.rest_mesh.nodes.size(); ++n)
    topology.rest_mesh.fixed[n] =
        body.inverse_masses().size() > n && body.inverse_masses()[n] == 0.0;
  return topology;
}

double total_mass(const BodyView& body) {
  double m = 0.0;
  for (const double v : body.masses())
    m += v;
  return m;
}

TEST(WorldTopology, a_split_tet_keeps_mass_and_rest_and_the_body_still_sags_alike) {
  World reference(hanging_block());
  World world(hanging_block());
  const double mass = total_mass(world.bodies()[0]);
  const std::size_t nodes = world.bodies()[0].node_count();
  const int tet = static_cast<int>(world.bodies()[0].tets().size() / 2);
  world.topology_changed(0, split_tet(world.bodies()[0], tet));
  ASSERT_EQ(world.bodies()[0].node_count(), nodes + 1);
  ASSERT_EQ(world.state().node_count(), nodes + 1);
  EXPECT_NEAR(total_mass(world.bodies()[0]), mass, 1e-12 * mass);
  // At rest nothing is loaded: the rebuilt terms agree with the new rest mesh.
  EXPECT_NEAR(world.energies().elastic, 0.0, 1e-15);
  for (int s = 0; s < 1500; ++s) {
    world.step();
    reference.step();
  }
  const double drop =
      world.bodies()[0].rest_centre_of_mass().z() - world.bodies()[0].centre_of_mass().z();
  const double reference_drop =
      reference.bodies()[0].rest_centre_of_mass().z() - reference.bodies()[0].centre_of_mass().z();
  ASSERT_GT(reference_drop, 1e-6);
  // One tet split in four is the same material: the sag changes by far less than 1 %.
  EXPECT_NEAR(drop, reference_drop, 0.01 * reference_drop);
  EXPECT_LT(world.energies().kinetic, 1e-9);
}

TEST(WorldTopology, a_split_while_deformed_keeps_every_cache_consistent_with_the_state) {
  // Two bodies with contact and an instrument: after the split every term sees the new ranges.
  core::Scenario scenario = hanging_block();
  core::SceneObject other = viscera::testing::held_block("other", 2, 2, 1, 0.01);
  for (auto& n : other.body.nodes)
    n.x() += 0.05;
  scenario.objects.push_back(other);
  World world(scenario);
  world.attach_instrument(1, 300.0, Vec3(0.06, 0.01, 0.03));
  for (int s = 0; s < 50; ++s)
    world.step();
  world.topology_changed(0, split_tet(world.bodies()[0], 3));
  EXPECT_EQ(world.bodies()[1].first_node(), static_cast<int>(world.bodies()[0].node_count()));
  // Press the second body with the tool: the proxy's surface follows the moved range.
  for (int s = 0; s < 100; ++s) {
    world.set_instrument_tip(Vec3(0.06, 0.01, 0.03 - 0.00022 * s));
    world.step();
  }
  EXPECT_TRUE(world.instrument_in_contact());
  EXPECT_EQ(world.instrument_touched_body(), 1);
  EXPECT_GT(world.bodies()[1].max_displacement(), 1e-4);
  for (const auto& p : world.state().positions)
    ASSERT_TRUE(p.allFinite());
}

}  // namespace
}  // namespace viscera::sim
