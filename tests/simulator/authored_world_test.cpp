// The world builds the authored terms (issue 16 part 2): active deformations move their host
// in the session, cell-agent objects are bodies, every tet body flows plastically and reports
// tears, and authoring mistakes are named.

#include <gtest/gtest.h>

#include <numbers>

#include "core/error.h"
#include "simulator/dynamics/authored_terms.h"
#include "simulator/dynamics/motility_forces.h"
#include "simulator/dynamics/plastic_flow.h"
#include "simulator/dynamics/pulse_waves.h"
#include "simulator/world/world.h"
#include "tests/simulator/sim_fixtures.h"

namespace viscera::sim {
namespace {

/// A 6 × 2 × 2 cm soft bowel-like block held at x = 0, no gravity.
core::Scenario bowel() {
  core::Scenario scenario;
  scenario.materials["soft"] = viscera::testing::soft_test_material();
  core::SceneObject block = viscera::testing::held_block("bowel", 6, 2, 2, 0.01);
  for (std::size_t n = 0; n < block.body.nodes.size(); ++n)
    block.body.fixed[n] = block.body.nodes[n].x() < 1e-9 ? 1 : 0;
  scenario.objects.push_back(block);
  scenario.session.gravity = core::Vec3::Zero();
  return scenario;
}

core::MotilitySpec peristalsis() {
  core::MotilitySpec spec;
  spec.amplitude_mean = 0.002;
  spec.wave_speed = 0.05;
  spec.frequency = 1.0;
  return spec;
}

template <class Term>
const Term* find_term(const World& world) {
  for (const auto& t : world.terms())
    if (const auto* found = dynamic_cast<const Term*>(t.get())) return found;
  return nullptr;
}

TEST(AuthoredWorld, motility_moves_the_host_at_its_frequency_and_keeps_the_world_awake) {
  core::Scenario scenario = bowel();
  scenario.active_deformations.push_back({"peristalsis", "bowel", peristalsis()});
  World world(scenario);
  world.set_sleep_threshold(1e-3);  // far above any motion here: only motility keeps it awake
  ASSERT_NE(find_term<MotilityForces>(world), nullptr);
  ASSERT_NE(find_term<PlasticFlow>(world), nullptr);
  const BodyView& body = world.bodies()[0];
  const std::size_t corner = body.node_count() - 1;
  std::vector<double> swing;
  for (int s = 0; s < 3000; ++s) {
    world.step();
    const core::Vec3 d = body.positions()[corner] - body.rest_positions()[corner];
    if ((s + 1) % 10 == 0) swing.push_back(d.y() + d.z());
  }
  EXPECT_FALSE(world.asleep());
  // Correlation with sines of 0.5 … 2 Hz over the last two seconds: strongest at 1 Hz.
  double best = 0.0, best_power = 0.0;
  for (double f = 0.5; f <= 2.0 + 1e-9; f += 0.05) {
    double c = 0.0, s = 0.0;
    for (std::size_t k = 100; k < swing.size(); ++k) {
      const double t = 0.01 * static_cast<double>(k + 1);
      c += swing[k] * std::cos(2.0 * std::numbers::pi * f * t);
      s += swing[k] * std::sin(2.0 * std::numbers::pi * f * t);
    }
    if (c * c + s * s > best_power) {
      best_power = c * c + s * s;
      best = f;
    }
  }
  EXPECT_NEAR(best, 1.0, 0.051);
  const auto [low, high] = std::minmax_element(swing.begin() + 100, swing.end());
  EXPECT_GT(*high - *low, 0.5e-3);
  // Without the deformation the same world stays at rest.
  World still(bowel());
  for (int s = 0; s < 100; ++s)
    still.step();
  EXPECT_EQ(still.bodies()[0].max_displacement(), 0.0);
}

TEST(AuthoredWorld, a_pulse_runs_down_the_vessel_tree_and_shakes_its_host) {
  core::Scenario scenario = bowel();
  core::VesselTree tree;
  tree.id = "mesenteric";
  tree.host_object = "bowel";
  const core::Vec3 fork(0.03, 0.01, 0.01);
  tree.segments = {{0, -1, core::Vec3(0.0, 0.01, 0.01), fork, 0.001, 0.0},
                   {1, 0, fork, core::Vec3(0.06, 0.0, 0.01), 0.0008, 0.0},
                   {2, 0, fork, core::Vec3(0.06, 0.02, 0.01), 0.0008, 0.0}};
  scenario.vessel_trees.push_back(tree);
  scenario.active_deformations.push_back(
      {"pulse", "bowel", core::PulseSpec{"mesenteric", 60.0, 1.0, 0.05}});
  World world(scenario);
  const PulseWaves* pulse = find_term<PulseWaves>(world);
  ASSERT_NE(pulse, nullptr);
  ASSERT_FALSE(pulse->knots().empty());
  const int first = world.bodies()[0].first_node();
  std::map<int, long long> arrival;
  for (long long s = 0; s < 100; ++s) {
    world.step();
    for (const int g : pulse->pushed())
      arrival.try_emplace(g - first, s);
  }
  const double h = world.time_step();
  for (const auto& knot : pulse->knots()) {
    if (knot.arc / 1.0 >= 0.1) continue;  // not reached in 100 ms
    ASSERT_TRUE(arrival.count(knot.node)) << knot.node;
    const double expected = knot.arc / 1.0;  // path length over the wave speed
    EXPECT_LE(static_cast<double>(arrival[knot.node]) * h, expected + 1e-12);
    EXPECT_GT(static_cast<double>(arrival[knot.node] + 1) * h, expected - 1e-12);
  }
  EXPECT_GT(world.bodies()[0].max_displacement(), 1e-6);
}

TEST(AuthoredWorld, names_a_deformation_without_body_or_vessel_tree) {
  core::Scenario no_body = bowel();
  no_body.active_deformations.push_back({"peristalsis", "stomach", peristalsis()});
  try {
    World world(no_body);
    FAIL() << "a deformation of a missing body was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("stomach"), std::string::npos) << e.what();
  }
  core::Scenario no_tree = bowel();
  no_tree.active_deformations.push_back(
      {"pulse", "bowel", core::PulseSpec{"aorta", 60.0, 5.0, 0.05}});
  try {
    World world(no_tree);
    FAIL() << "a pulse on a missing vessel tree was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("aorta"), std::string::npos) << e.what();
  }
}

TEST(AuthoredWorld, a_cell_agent_object_is_a_body_the_instrument_presses) {
  core::Scenario scenario;
  scenario.session.gravity = core::Vec3::Zero();
  scenario.session.time_step = 5e-4;
  core::SceneObject sheet;
  sheet.id = "tissue";
  sheet.body_kind = core::BodyKind::CellAgent;
  core::CellTissueSpec spec;
  spec.object = "tissue";
  spec.types = {core::CellTypeSpec{}};
  spec.neighbour_radius = 0.00105;
  const int n = 12;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      sheet.body.nodes.emplace_back(0.001 * i, 0.001 * j, 0.0);
      sheet.body.node_mass.push_back(1e-4);
      sheet.body.fixed.push_back(j == 0 || j == n - 1 || i == 0 || i == n - 1 ? 1 : 0);
      spec.cell_types.push_back(0);
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      sheet.body.surface_faces.push_back({a, b, d});
      sheet.body.surface_faces.push_back({a, d, c});
    }
  scenario.objects.push_back(sheet);
  scenario.cell_tissues.push_back(spec);
  World world(scenario);
  ASSERT_EQ(world.bodies().size(), 1u);
  EXPECT_EQ(world.bodies()[0].node_count(), 144u);
  const std::string at_rest = world.state_hash();
  world.attach_instrument(0, 200.0, core::Vec3(0.0055, 0.0055, 0.005));
  for (int s = 0; s < 2000; ++s) {
    world.set_instrument_tip(core::Vec3(0.0055, 0.0055, 0.005 - 0.007 * std::min(1.0, s / 1500.0)));
    world.step();
  }
  EXPECT_TRUE(world.instrument_in_contact());
  EXPECT_GT(world.instrument_force().z(), 0.0);  // the sheet pushes the probe back up
  EXPECT_GT(world.bodies()[0].max_displacement(), 1e-3);
  EXPECT_NE(world.state_hash(), at_rest);
  // A cell tissue whose object is missing its masses is named.
  core::Scenario massless = scenario;
  massless.objects[0].body.node_mass.clear();
  EXPECT_THROW(World{massless}, core::InputError);
}

}  // namespace
}  // namespace viscera::sim
