#include "textures/active_deformation_specs.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace viscera::textures {
namespace {

core::VesselTree straight_tree(double length) {
  core::VesselTree tree;
  tree.id = "uterine-artery";
  tree.host_object = "uterus";
  tree.segments = {{0, -1, {0, 0, 0}, {0, 0, length / 2}, 0.002, 1e-6},
                   {1, 0, {0, 0, length / 2}, {0, 0, length}, 0.002, 1e-6}};
  return tree;
}

core::Scenario scenario_with(const core::ActiveDeformation& deformation) {
  core::Scenario scenario;
  core::SceneObject uterus;
  uterus.id = "uterus";
  scenario.objects.push_back(uterus);
  scenario.vessel_trees.push_back(straight_tree(0.1));
  scenario.active_deformations.push_back(deformation);
  return scenario;
}

bool has_error_at(const std::vector<SpecIssue>& issues, const std::string& pointer) {
  for (const auto& issue : issues) {
    if (issue.error && issue.json_pointer == pointer) return true;
  }
  return false;
}

TEST(PulseSpec, physiological_values_pass) {
  const auto pulse = make_pulse("pulse", "uterus", straight_tree(0.1), 72, 8.0, 0.05);
  EXPECT_TRUE(validate_active_deformations(scenario_with(pulse)).empty());
}

TEST(PulseSpec, each_bad_member_is_reported_with_its_pointer) {
  core::PulseSpec spec;
  spec.vessel_tree = "nowhere";
  spec.heart_rate = 400;
  spec.pulse_velocity = -1;
  spec.wall_force = 0;
  const auto issues = validate_active_deformations(scenario_with({"p", "liver", spec}));
  for (const char* member :
       {"/pulse/heart_rate", "/pulse/pulse_velocity", "/pulse/wall_force", "/pulse/vessel_tree"}) {
    EXPECT_TRUE(has_error_at(issues, std::string("/scenario/active_deformations/0") + member))
        << member;
  }
  EXPECT_TRUE(has_error_at(issues, "/scenario/active_deformations/0/target_object"));
  EXPECT_THROW(make_pulse("p", "uterus", straight_tree(0.1), 10, 8, 0.05), core::ValidationError);
}

TEST(PulseSpec, warns_when_waves_cannot_cross_the_tree_within_a_beat) {
  // Seed 001 §5.1.1: a fast heart and a slow wave delete waves before they arrive.
  core::PulseSpec spec;
  spec.vessel_tree = "uterine-artery";
  spec.heart_rate = 150;      // 0.4 s per beat
  spec.pulse_velocity = 0.2;  // 0.5 s for 0.1 m
  core::Scenario scenario = scenario_with({"p", "uterus", spec});
  const auto issues = validate_pulse_spec(spec, &scenario, "/pulse");
  ASSERT_EQ(issues.size(), 2u);  // the slow velocity itself, and the transit
  for (const auto& issue : issues)
    EXPECT_FALSE(issue.error) << issue.message;
  EXPECT_NEAR(longest_wave_path(scenario.vessel_trees[0]), 0.1, 1e-15);
}

TEST(PulseSpec, one_pulse_per_vessel_tree) {
  core::Scenario scenario =
      scenario_with(make_pulse("a", "uterus", straight_tree(0.1), 70, 6, 0.05));
  scenario.active_deformations.push_back(
      make_pulse("b", "uterus", straight_tree(0.1), 70, 9, 0.05));
  EXPECT_TRUE(has_error_at(validate_active_deformations(scenario),
                           "/scenario/active_deformations/1/pulse/vessel_tree"));
}

TEST(MotilitySpec, physiological_values_pass_and_bad_ones_point_at_their_member) {
  core::MotilitySpec m;
  m.amplitude_mean = 0.003;
  m.amplitude_variance = 1e-6;  // 1 mm deviation
  m.wave_speed = 0.01;
  m.wave_direction = core::Vec3(0, 0, 1);
  m.frequency = 0.05;  // 3 per minute, gastric
  m.frequency_disturbance = 0.01;
  m.contraction_interval_mean = 20;
  m.contraction_interval_variance = 25;
  EXPECT_TRUE(validate_motility_spec(m, "/m").empty());
  EXPECT_NO_THROW(make_motility("motility", "uterus", m));

  core::MotilitySpec bad = m;
  bad.amplitude_mean = 0.2;
  bad.wave_direction = core::Vec3(1, 1, 0);
  bad.frequency = 0;
  bad.frequency_disturbance = 0.5;
  bad.contraction_interval_mean = 0;
  const auto issues = validate_motility_spec(bad, "/m");
  for (const char* member : {"/m/amplitude_mean", "/m/wave_direction", "/m/frequency",
                             "/m/frequency_disturbance", "/m/contraction_interval_variance"}) {
    EXPECT_TRUE(has_error_at(issues, member)) << member;
  }
  EXPECT_THROW(make_motility("motility", "uterus", bad), core::ValidationError);
}

}  // namespace
}  // namespace viscera::textures
