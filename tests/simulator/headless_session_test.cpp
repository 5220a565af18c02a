#include "simulator/session/headless_session.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "simulator/world/world.h"
#include "tests/simulator/sim_fixtures.h"

namespace viscera::sim {
namespace {

/// A 3 × 3 × 6 cm soft block standing on its fixed base, under gravity.
core::Scenario standing_block(double time_step = 1e-3) {
  core::Scenario scenario;
  scenario.metadata.name = "block";
  core::Material material;
  material.id = "soft";
  material.density = 1000.0;
  material.distance_stiffness = 30000.0;
  material.volume_stiffness = 30000.0;
  material.area_stiffness = 1.0;
  material.distance_damping = 100.0;
  scenario.materials[material.id] = material;
  core::SceneObject block;
  block.id = "block";
  block.material = "soft";
  block.body_kind = core::BodyKind::TetMesh;
  block.body = viscera::testing::tet_block(3, 3, 6, 0.01);
  block.body.fixed.assign(block.body.nodes.size(), 0);
  for (std::size_t n = 0; n < block.body.nodes.size(); ++n) {
    if (block.body.nodes[n].z() < 1e-9) block.body.fixed[n] = 1;
  }
  scenario.objects.push_back(block);
  scenario.session.time_step = time_step;
  scenario.session.tasks.push_back(
      {"settle", "settle", "settle", {{"kinetic_energy_below", 2e-8}, {"hold_time", 0.05}}});
  scenario.session.tasks.push_back({"cut", "cut the block", "cut", {}});
  return scenario;
}

TEST(HeadlessSession, clamped_block_sags_and_comes_to_rest_with_decreasing_energy) {
  HeadlessRunOptions options;
  options.duration = 4.0;  // the slender block rocks with a period of about 0.4 s
  options.settle = false;  // the sag itself is what this test watches
  const SessionReport report = run_headless(standing_block(), options);
  ASSERT_FALSE(report.samples.empty());
  // Sags: the centre of mass moves down along gravity, by a few millimetres.
  ASSERT_EQ(report.bodies.size(), 1u);
  EXPECT_GT(report.bodies[0].centre_of_mass_drop, 1e-4);
  EXPECT_LT(report.bodies[0].centre_of_mass_drop, 0.02);
  // Energy decreases under damping: total energy never rises by more than Verlet's wobble and
  // ends well below zero (potential released, dissipated by damping).
  double peak_kinetic = 0.0;
  for (std::size_t i = 1; i < report.samples.size(); ++i) {
    EXPECT_LE(report.samples[i].total(), report.samples[i - 1].total() + 1e-6)
        << "at t=" << report.samples[i].time;
    peak_kinetic = std::max(peak_kinetic, report.samples[i].kinetic);
  }
  EXPECT_LT(report.samples.back().total(), -1e-4);
  // Comes to rest: the final kinetic energy is a tiny fraction of its peak.
  EXPECT_LT(report.samples.back().kinetic, 1e-3 * peak_kinetic);
  EXPECT_EQ(report.tasks[0].status, "completed");
  EXPECT_GT(report.tasks[0].completed_at, 0.0);
  EXPECT_EQ(report.tasks[1].status, "unavailable");
}

TEST(HeadlessSession, two_runs_give_the_same_state_hash) {
  HeadlessRunOptions options;
  options.duration = 0.3;
  const auto a = run_headless(standing_block(), options);
  const auto b = run_headless(standing_block(), options);
  EXPECT_EQ(a.final_state_hash, b.final_state_hash);
  EXPECT_EQ(a.final_state_hash.size(), 64u);
}

TEST(HeadlessSession, the_hash_sees_a_one_part_per_million_change) {
  HeadlessRunOptions options;
  options.duration = 0.3;
  core::Scenario heavier = standing_block();
  heavier.materials["soft"].density *= 1.000001;
  heavier.objects[0].body.node_mass.clear();  // masses follow the density
  core::Scenario reference = standing_block();
  reference.objects[0].body.node_mass.clear();
  EXPECT_NE(run_headless(reference, options).final_state_hash,
            run_headless(heavier, options).final_state_hash);
}

TEST(HeadlessSession, report_json_has_the_documented_fields) {
  HeadlessRunOptions options;
  options.duration = 0.1;
  options.package = "block.vscene";
  const auto json = report_to_json(run_headless(standing_block(), options));
  EXPECT_EQ(json["format"], "viscera-session-report");
  EXPECT_EQ(json["version"], 3);
  EXPECT_TRUE(json["score"].is_null());  // no instrument: nothing to assess
  EXPECT_TRUE(json["score_reason"].is_string());
  EXPECT_TRUE(json["realtime"].is_null());  // headless
  EXPECT_EQ(json["steps"], 100);
  EXPECT_NEAR(json["simulated_time"].get<double>(), 0.1, 1e-12);
  EXPECT_EQ(json["package"], "block.vscene");
  for (const char* series :
       {"time", "kinetic", "elastic", "gravitational", "total", "max_displacement"}) {
    EXPECT_EQ(json["energy"][series].size(), json["energy"]["time"].size()) << series;
  }
  EXPECT_GT(json["energy"]["time"].size(), 5u);
  EXPECT_GE(json["max_displacement"].get<double>(), 0.0);
  EXPECT_EQ(json["bodies"][0]["tets"], 3 * 3 * 6 * 6);
  EXPECT_EQ(json["tasks"].size(), 2u);
}

TEST(World, splits_the_step_when_the_body_needs_it_and_stays_finite) {
  core::Scenario stiff = standing_block();
  stiff.materials["soft"].distance_stiffness = 3.0e6;
  stiff.materials["soft"].volume_stiffness = 3.0e6;
  World world(stiff, IntegratorKind::ExplicitVerlet);
  EXPECT_GT(world.substeps(), 1);
  for (int s = 0; s < 200; ++s)
    world.step();
  for (const auto& p : world.bodies()[0].positions())
    ASSERT_TRUE(p.allFinite());
  EXPECT_LT(world.bodies()[0].max_displacement(), 0.01);
}

TEST(World, refuses_an_unknown_material) {
  core::Scenario scenario = standing_block();
  scenario.objects[0].material = "missing";
  EXPECT_THROW(World{scenario}, core::InputError);
}

TEST(HeadlessSession, refuses_a_non_positive_duration) {
  HeadlessRunOptions options;
  options.duration = 0.0;
  EXPECT_THROW(run_headless(standing_block(), options), core::UsageError);
}

}  // namespace
}  // namespace viscera::sim

namespace viscera::sim {
namespace {

/// A 10 × 2 × 2 cm beam clamped at x = 0, lying along x under gravity.
core::Scenario clamped_beam(core::BodyKind kind) {
  core::Scenario scenario = standing_block();
  auto& beam = scenario.objects[0];
  beam.body_kind = kind;
  beam.body = viscera::testing::tet_block(10, 2, 2, 0.01);
  beam.body.fixed.assign(beam.body.nodes.size(), 0);
  for (std::size_t n = 0; n < beam.body.nodes.size(); ++n)
    beam.body.fixed[n] = beam.body.nodes[n].x() < 1e-9;
  scenario.materials["soft"].distance_stiffness = 2.0e5;
  scenario.materials["soft"].volume_stiffness = 2.0e5;
  scenario.materials["soft"].distance_damping =
      2000.0;  // bending is damped only through edge strain
  scenario.session.tasks.clear();
  return scenario;
}

class ClampedBeam : public ::testing::TestWithParam<core::BodyKind> {};

TEST_P(ClampedBeam, sags_at_the_free_end_and_comes_to_rest) {
  HeadlessRunOptions options;
  options.duration = 3.0;
  const core::Scenario scenario = clamped_beam(GetParam());
  World world(scenario);
  double peak_kinetic = 0.0;
  for (int s = 0; s < 3000; ++s) {
    world.step();
    peak_kinetic = std::max(peak_kinetic, world.energies().kinetic);
  }
  const auto& body = world.bodies()[0];
  // The free end (x = 10 cm) hangs lower than the clamped end, which has not moved.
  double tip_drop = 0.0;
  for (std::size_t n = 0; n < body.node_count(); ++n) {
    if (body.rest_positions()[n].x() > 0.0999)
      tip_drop = std::max(tip_drop, body.rest_positions()[n].z() - body.positions()[n].z());
    if (body.rest_positions()[n].x() < 1e-9) {
      EXPECT_EQ(body.positions()[n], body.rest_positions()[n]);
    }
  }
  EXPECT_GT(tip_drop, 1e-3);
  // Euler–Bernoulli, δ = ρ g A L⁴ / (8 E I), gives about 9 cm for the edge network's effective
  // modulus (≈ distance_stiffness / 5); the Teschner volume terms stiffen it further. Either
  // way the free end stays above the clamp's foot by less than the beam's length.
  EXPECT_LT(tip_drop, 0.1);
  EXPECT_LT(world.energies().kinetic, 1e-3 * peak_kinetic);
  EXPECT_LT(world.energies().total(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Models, ClampedBeam,
                         ::testing::Values(core::BodyKind::TetMesh, core::BodyKind::MassSpring),
                         [](const auto& kind) {
                           return core::to_string(kind.param) == "tet-mesh"
                                      ? std::string("Teschner")
                                      : std::string("Kismo");
                         });

}  // namespace
}  // namespace viscera::sim
