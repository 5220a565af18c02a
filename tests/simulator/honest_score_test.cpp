// Honest scores (issue 16 item 4): a session in which the trainee did nothing has no score and
// says why; a task that cannot be assessed never counts as done, so a session with no input
// never "completes" a procedure; and a state gone non-finite is a typed SimulationError that
// names the body, the node and the step.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "simulator/session/headless_session.h"
#include "simulator/session/manual_control.h"
#include "simulator/session/session_runner.h"
#include "simulator/session/simulation_check.h"
#include "templates/template_catalog.h"
#include "tests/simulator/session_fixtures.h"
#include "tests/support/tet_block.h"

namespace viscera::sim {
namespace {

TEST(HonestScore, an_untouched_session_has_no_score_and_says_why) {
  const core::Scenario scenario = viscera::testing::cavity_scenario();
  // The trainee's instrument rests where a session starts and never moves.
  const RecordedInput resting({{0, starting_pose(scenario, 30.0)}});
  HeadlessRunOptions options;
  options.duration = 0.5;
  options.instrument = &resting;
  options.instrument_body = "uterus";
  const SessionReport report = run_headless(scenario, options);
  EXPECT_FALSE(report.score.has_value());
  EXPECT_NE(report.score_reason.find("never moved"), std::string::npos) << report.score_reason;
  EXPECT_NE(report.end_reason, "completed");
  for (const auto& task : report.tasks)
    EXPECT_NE(task.status, "completed") << task.id;
  for (const auto& step : report.procedure_steps) {
    EXPECT_FALSE(step.score.has_value()) << step.id;
    EXPECT_FALSE(step.score_reason.empty()) << step.id;
  }
  const nlohmann::json json = report_to_json(report);
  EXPECT_TRUE(json["score"].is_null());
  EXPECT_TRUE(json["score_reason"].is_string());
  EXPECT_EQ(json["version"], 3);
}

TEST(HonestScore, a_scripted_session_that_moves_is_scored) {
  const core::Scenario scenario = viscera::testing::cavity_scenario();
  const auto script =
      ScriptedTrajectory::from_json(viscera::testing::expert_cavity_script(), "expert");
  HeadlessRunOptions options;
  options.duration = script.duration() + 1.0;
  options.instrument = &script;
  options.instrument_body = "uterus";
  const SessionReport report = run_headless(scenario, options);
  ASSERT_TRUE(report.score.has_value()) << report.score_reason;
  EXPECT_GT(*report.score, 50.0);
  EXPECT_TRUE(report.score_reason.empty());
  EXPECT_TRUE(report_to_json(report)["score_reason"].is_null());
}

TEST(HonestScore, laparoscopy_gyn_with_no_input_has_no_score_and_is_not_completed) {
  const core::Scenario scenario = templates::build_from_template("laparoscopy-gyn", {}, 1);
  HeadlessRunOptions options;
  options.duration = 0.2;
  const SessionReport report = run_headless(scenario, options);
  EXPECT_NE(report.end_reason, "completed");
  EXPECT_NEAR(report.simulated_time, 0.2, 1e-9);  // it ran on: nothing was completed at 0 s
  EXPECT_FALSE(report.score.has_value());
  EXPECT_NE(report.score_reason.find("no instrument"), std::string::npos) << report.score_reason;
  ASSERT_FALSE(report.tasks.empty());
  for (const auto& task : report.tasks) {
    EXPECT_EQ(task.status, "unavailable") << task.id;
    EXPECT_FALSE(task.note.empty()) << task.id;
  }
  EXPECT_EQ(report.metrics.tasks_available(), 0);
  EXPECT_EQ(report.metrics.tasks_completed(), 0);
}

TEST(HonestScore, a_step_without_assessable_tasks_never_completes_by_itself) {
  // The cavity's diagnostic procedure with a grasping task added to its last step: the
  // expert's script completes every task this runtime detects, yet the procedure is not
  // reported as complete, and the grasp stays "unavailable", never done.
  core::Scenario scenario = viscera::testing::cavity_scenario();
  ASSERT_FALSE(scenario.session.steps.empty());
  core::TaskSpec grasp;
  grasp.id = "grasp-polyp";
  grasp.kind = "grasp";
  grasp.parameters = nlohmann::json::object();
  scenario.session.steps.back().substeps.back().tasks.push_back(grasp);
  const auto script =
      ScriptedTrajectory::from_json(viscera::testing::expert_cavity_script(), "expert");
  HeadlessRunOptions options;
  options.duration = script.duration() + 1.0;
  options.instrument = &script;
  options.instrument_body = "uterus";
  const SessionReport report = run_headless(scenario, options);
  EXPECT_NE(report.end_reason, "completed");
  bool said = false;
  for (const auto& event : report.events)
    said = said || event.kind == "procedure-unassessable";
  EXPECT_TRUE(said);
  for (const auto& task : report.tasks) {
    if (task.id == "grasp-polyp")
      EXPECT_EQ(task.status, "unavailable");
    else
      EXPECT_EQ(task.status, "completed") << task.id << " " << task.note;
  }
  EXPECT_EQ(report.metrics.tasks_completed(), report.metrics.tasks_available());
  EXPECT_EQ(report.metrics.tasks_available(), static_cast<int>(report.tasks.size()) - 1);
}

TEST(SimulationFailure, a_non_finite_node_is_named_with_body_step_and_cause) {
  const core::Scenario scenario = viscera::testing::cavity_scenario();
  World world(scenario);
  world.step();
  EXPECT_FALSE(find_state_fault(world).has_value());
  auto& body = world.bodies()[0];
  body.positions()[7] = core::Vec3(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  const auto fault = find_state_fault(world);
  ASSERT_TRUE(fault.has_value());
  EXPECT_EQ(fault->body, body.name());
  EXPECT_EQ(fault->node, 7);
  const core::SimulationError error = simulation_error(*fault, 2, 0.002);
  EXPECT_EQ(error.body(), body.name());
  EXPECT_EQ(error.node(), 7);
  EXPECT_EQ(error.step(), 2);
  EXPECT_FALSE(error.cause().empty());
  const std::string text = error.what();
  EXPECT_NE(text.find("node 7"), std::string::npos) << text;
  EXPECT_NE(text.find("step 2"), std::string::npos) << text;
  EXPECT_NE(text.find("likely cause"), std::string::npos) << text;
  EXPECT_EQ(text.find('\n'), std::string::npos) << "one sentence, one line";
  EXPECT_EQ(core::exit_code_for(error), core::ExitCode::SimulationFailed);
}

TEST(SimulationFailure, a_session_whose_state_goes_non_finite_throws_it_typed) {
  // A tool pressing on the tissue whose tip then turns into not-a-number (no shipped input can
  // send one: scripts and device packets refuse them) drags the proxy spring, and with it the
  // tissue, into NaN.
  core::Scenario scenario = viscera::testing::held_soft_block();
  scenario.session.gravity = core::Vec3::Zero();
  InstrumentState above;
  above.tip = {0.02, 0.021, 0.03};
  InstrumentState pressing = above;
  pressing.tip = {0.02, 0.021, 0.017};  // 3 mm into the top face: the proxy holds on it
  InstrumentState broken = above;
  broken.tip = {0.02, 0.021, std::numeric_limits<double>::quiet_NaN()};
  const RecordedInput input({{0, above}, {1, pressing}, {5, broken}});
  HeadlessRunOptions options;
  options.duration = 0.5;
  options.instrument = &input;
  try {
    run_headless(scenario, options);
    FAIL() << "a non-finite state went unnoticed";
  } catch (const core::SimulationError& e) {
    EXPECT_EQ(e.body(), "block");
    EXPECT_GE(e.step(), 5);
    EXPECT_LE(e.step(), 40);  // noticed by the next sample at the latest (every 20 steps)
    EXPECT_FALSE(e.cause().empty());
    EXPECT_EQ(core::exit_code_for(e), core::ExitCode::SimulationFailed);
  }
}

TEST(SimulationFailure, a_crushed_body_names_its_inverted_tets_as_the_cause) {
  const core::Scenario scenario = viscera::testing::cavity_scenario();
  World world(scenario);
  auto& body = world.bodies()[0];
  // Mirror every node through the plane x = 0: every tet turns inside out; one node is lost.
  for (auto& p : body.positions())
    p.x() = -p.x();
  body.positions()[3] = core::Vec3::Constant(std::numeric_limits<double>::infinity());
  const auto fault = find_state_fault(world);
  ASSERT_TRUE(fault.has_value());
  EXPECT_GT(fault->inverted_tets, 0);
  const core::SimulationError error = simulation_error(*fault, 5, 0.005);
  EXPECT_NE(error.cause().find("inverted tets"), std::string::npos) << error.cause();
}

}  // namespace
}  // namespace viscera::sim
