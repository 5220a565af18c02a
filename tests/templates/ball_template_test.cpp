#include "templates/ball_template.h"

#include <gtest/gtest.h>

#include <numbers>

#include "core/error.h"
#include "simulator/session/headless_session.h"
#include "templates/template_catalog.h"

namespace viscera::templates {
namespace {

core::Scenario small_ball() {
  return build_from_template("ball", {{"radius", "0.03"}, {"cell_size", "0.008"}}, 5);
}

TEST(BallTemplate, builds_a_valid_sphere_body_with_fixed_base_and_provenance) {
  const core::Scenario scenario = small_ball();
  ASSERT_EQ(scenario.objects.size(), 1u);
  const auto& ball = scenario.objects[0];
  EXPECT_EQ(ball.body_kind, core::BodyKind::TetMesh);
  EXPECT_NO_THROW(core::check_tet_mesh(ball.body, "ball"));
  const double sphere = 4.0 / 3.0 * std::numbers::pi * 0.03 * 0.03 * 0.03;
  EXPECT_NEAR(core::total_volume(ball.body), sphere, 0.05 * sphere);  // inscribed polyhedron
  EXPECT_TRUE(core::is_closed_and_consistently_oriented(ball.surface));
  EXPECT_EQ(ball.embedding.tet.size(), ball.surface.vertices.size());
  // Fixed nodes: exactly those in the lowest tenth of the diameter.
  int fixed = 0;
  for (std::size_t n = 0; n < ball.body.nodes.size(); ++n) {
    const bool low = ball.body.nodes[n].z() <= -0.03 + 0.006;
    EXPECT_EQ(ball.body.fixed[n] != 0, low) << n;
    fixed += low;
  }
  EXPECT_GT(fixed, 3);
  EXPECT_EQ(scenario.provenance.template_name, "ball");
  EXPECT_EQ(scenario.provenance.seed, 5u);
  EXPECT_DOUBLE_EQ(scenario.provenance.parameters["radius"].get<double>(), 0.03);
  EXPECT_TRUE(scenario.provenance.tool_versions.contains("gmsh"));
}

TEST(BallTemplate, sags_under_gravity_and_comes_to_rest_with_decreasing_energy) {
  sim::HeadlessRunOptions options;
  options.duration = 3.0;
  const sim::SessionReport report = sim::run_headless(small_ball(), options);
  EXPECT_GT(report.bodies[0].centre_of_mass_drop, 1e-4);  // it sags …
  EXPECT_LT(report.bodies[0].centre_of_mass_drop, 0.01);  // … but stays a ball
  for (std::size_t i = 1; i < report.samples.size(); ++i) {
    EXPECT_LE(report.samples[i].total(), report.samples[i - 1].total() + 1e-7)
        << report.samples[i].time;
  }
  EXPECT_EQ(report.tasks[0].status, "completed")
      << "kinetic energy at the end " << report.samples.back().kinetic;
}

TEST(TemplateCatalog, resolves_overrides_and_refuses_bad_ones) {
  const auto& ball = find_template("ball");
  const auto values = resolve_parameters(ball, {{"radius", "0.05"}});
  EXPECT_DOUBLE_EQ(values.at("radius"), 0.05);
  EXPECT_DOUBLE_EQ(values.at("cell_size"), 0.008);
  EXPECT_THROW(resolve_parameters(ball, {{"radius", "huge"}}), core::UsageError);
  EXPECT_THROW(resolve_parameters(ball, {{"radius", "5"}}), core::UsageError);
  EXPECT_THROW(resolve_parameters(ball, {{"colour", "red"}}), core::UsageError);
  EXPECT_THROW(resolve_parameters(ball, {{"visual_subdivisions", "1.5"}}), core::UsageError);
  EXPECT_THROW(find_template("spleen"), core::UsageError);
}

TEST(TemplateCatalog, same_seed_and_parameters_build_the_same_scenario) {
  EXPECT_EQ(small_ball(), small_ball());
}

}  // namespace
}  // namespace viscera::templates

namespace viscera::templates {
namespace {

TEST(BallTemplate, on_the_floor_the_two_bodies_touch_without_interpenetrating) {
  const core::Scenario scenario =
      build_from_template("ball", {{"radius", "0.03"}, {"cell_size", "0.01"}, {"floor", "1"}}, 2);
  ASSERT_EQ(scenario.objects.size(), 2u);
  EXPECT_EQ(scenario.objects[1].role, core::ObjectRole::Fixture);
  sim::HeadlessRunOptions options;
  options.duration = 0.5;
  const sim::SessionReport report = sim::run_headless(scenario, options);
  int touching_samples = 0;
  for (const auto& s : report.samples)
    touching_samples += s.colliding_points > 0;
  EXPECT_GT(touching_samples,
            static_cast<int>(report.samples.size()) / 2);  // it rests on the floor
  EXPECT_GT(report.max_penetration, 0.0);
  EXPECT_LT(report.max_penetration, 1e-3);  // under a millimetre, a tenth of the cell size
  EXPECT_GT(report.bodies[0].centre_of_mass_drop, 0.0);
  EXPECT_LT(report.bodies[0].centre_of_mass_drop,
            0.015);                                   // held up by the floor, not falling through
  EXPECT_EQ(report.bodies[1].max_displacement, 0.0);  // the floor is fixed
}

}  // namespace
}  // namespace viscera::templates
