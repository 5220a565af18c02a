#include "simulator/session/session_runner.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/scenario/procedure.h"
#include "simulator/session/headless_session.h"
#include "simulator/session/session_trace.h"
#include "tests/simulator/session_fixtures.h"

namespace viscera::sim {
namespace {

SessionReport run(const core::Scenario& scenario, const InstrumentInput& input, double duration,
                  bool record = false) {
  HeadlessRunOptions options;
  options.duration = duration;
  options.instrument = &input;
  options.instrument_body = "uterus";
  options.record_inputs = record;
  return run_headless(scenario, options);
}

const TaskResult& task(const SessionReport& report, const std::string& id) {
  for (const auto& t : report.tasks) {
    if (t.id == id) return t;
  }
  throw std::runtime_error("no task " + id);
}

TEST(SessionRunner, expert_and_novice_separate_on_every_metric_in_the_expected_direction) {
  const core::Scenario scenario = viscera::testing::cavity_scenario();
  const auto expert_script =
      ScriptedTrajectory::from_json(viscera::testing::expert_cavity_script(), "expert");
  const auto novice_script =
      ScriptedTrajectory::from_json(viscera::testing::novice_cavity_script(), "novice");
  const SessionReport e = run(scenario, expert_script, expert_script.duration() + 1.0);
  const SessionReport n = run(scenario, novice_script, novice_script.duration() + 1.0);
  for (const auto& t : e.tasks)
    EXPECT_EQ(t.status, "completed") << t.id << " " << t.note;
  EXPECT_EQ(e.end_reason, "completed");
  const SessionMetrics& a = e.metrics;
  const SessionMetrics& b = n.metrics;
  EXPECT_LT(a.duration(), b.duration());
  EXPECT_LT(a.path_length(), b.path_length());
  EXPECT_GT(a.economy(), b.economy());
  EXPECT_GT(a.economy(), 0.9);
  EXPECT_LT(a.contacts(), b.contacts());
  EXPECT_GE(b.contacts(), 3);
  EXPECT_LT(a.contact_time(), b.contact_time());
  EXPECT_LT(a.max_force(), b.max_force());
  EXPECT_LT(a.mean_force(), b.mean_force());
  EXPECT_GT(a.surface_seen(), b.surface_seen());
  EXPECT_GE(a.surface_seen(), 0.35);
  EXPECT_GT(a.view_quality(), b.view_quality());
  EXPECT_GT(a.tasks_completed(), b.tasks_completed());
  ASSERT_TRUE(e.score.has_value() && n.score.has_value());
  EXPECT_GT(*e.score, *n.score);
  EXPECT_EQ(task(n, "centre-left").status, "not-completed");
  // The novice pushed past the warning level: logged as events; the expert never did.
  int warnings = 0;
  for (const auto& event : n.events)
    warnings += event.kind == "excessive-force";
  EXPECT_GE(warnings, 1);
  for (const auto& event : e.events)
    EXPECT_NE(event.kind, "excessive-force");
  // Per step: every step of the expert's has a start, an end and its share of the path.
  ASSERT_EQ(e.procedure_steps.size(), 3u);
  double path = 0.0;
  for (const auto& step : e.procedure_steps) {
    EXPECT_GE(step.started_at, 0.0);
    EXPECT_GT(step.ended_at, step.started_at) << step.id;
    path += step.metrics.path_length();
  }
  EXPECT_NEAR(path, a.path_length(), 1e-9);
  EXPECT_GT(e.procedure_steps[1].metrics.surface_seen(), 0.3);  // the panorama is in "inspect"
  // The path samples know the distance to the wall: inside a 15 mm cavity it is at most 15 mm.
  for (const auto& p : e.path)
    EXPECT_LE(p.wall_distance, viscera::testing::kCavityRadius + 1e-3);
}

TEST(SessionRunner, distension_fluid_is_balanced_and_an_overload_ends_the_session) {
  core::Scenario scenario = viscera::testing::cavity_scenario();
  scenario.fluid.enabled = true;
  const core::Vec3 centre(0.0, 0.0, 0.0), up(0.0, 0.0, 0.02);
  // Inflow open, outflow shut, the scope held still at the centre of the cavity.
  nlohmann::json still =
      viscera::testing::cavity_script({{0.0, {centre, up}}, {3.0, {centre, up}}});
  still["waypoints"][0]["inflow"] = 1.0;
  still["waypoints"][0]["outflow"] = 0.0;
  const auto script = ScriptedTrajectory::from_json(still, "still");

  SessionReport report = run(scenario, script, 3.0);
  ASSERT_TRUE(report.fluid.has_value());
  const FluidTotals& fluid = *report.fluid;
  // Nothing drains with the outflow shut: what went in is in the cavity or absorbed.
  EXPECT_EQ(fluid.drained, 0.0);
  const DistensionChannels channels;
  EXPECT_NEAR(fluid.used,
              channels.cavity_compliance * report.final_cavity_pressure + fluid.absorbed, 1e-12);
  EXPECT_GT(report.final_cavity_pressure, 5000.0);  // the pump filled the cavity
  EXPECT_DOUBLE_EQ(report_to_json(report)["metrics"]["distension_fluid_used"].get<double>(),
                   fluid.used);
  EXPECT_EQ(report.end_reason, "duration");

  // The same with a 2 ml overload limit: the deficit reaches it within a second or two.
  scenario.fluid.overload_volume = 2e-6;
  report = run(scenario, script, 3.0);
  EXPECT_EQ(report.end_reason, "fluid-overload");
  EXPECT_EQ(report.events.back().kind, "fluid-overload");
  EXPECT_LT(report.simulated_time, 3.0);
  EXPECT_GE(report.fluid->deficit(), 2e-6);

  // Without fluid in the scenario the metric says so.
  scenario.fluid.enabled = false;
  report = run(scenario, script, 0.2);
  EXPECT_FALSE(report.fluid.has_value());
  EXPECT_TRUE(report_to_json(report)["metrics"]["distension_fluid_used"].is_null());
}

TEST(SessionRunner, pushing_through_the_wall_perforates_it_and_ends_the_session) {
  const core::Scenario scenario = viscera::testing::cavity_scenario();
  const core::Vec3 up(0.0, 0.0, 0.02);
  // Straight through the fundus wall (7 mm) to 2 cm beyond the cavity.
  const auto script = ScriptedTrajectory::from_json(
      viscera::testing::cavity_script(
          {{0.0, {{0.0, 0.0, 0.0}, up}}, {2.0, {{0.0011, 0.0007, 0.035}, {0.0, 0.0, 0.05}}}}),
      "push");
  const SessionReport report = run(scenario, script, 3.0);
  EXPECT_EQ(report.end_reason, "perforation");
  ASSERT_FALSE(report.events.empty());
  EXPECT_EQ(report.events.back().kind, "perforation");
  // Perforated when the tip passed the wall's rest thickness (measured from the surface, no
  // depth given): the cavity wall is at 15 mm, the outer surface at 22 mm, the tip moves at
  // 17.5 mm/s from the centre.
  const double through =
      (viscera::testing::kCavityRadius + viscera::testing::kWallThickness) / 0.0175;
  EXPECT_NEAR(report.simulated_time, through, 0.08);
}

TEST(SessionRunner, time_limit_and_trainee_abort_end_the_session) {
  core::Scenario scenario = viscera::testing::cavity_scenario();
  scenario.session.duration_limit = 0.5;
  const auto expert =
      ScriptedTrajectory::from_json(viscera::testing::expert_cavity_script(), "expert");
  const SessionReport limited = run(scenario, expert, 20.0);
  EXPECT_EQ(limited.end_reason, "time-limit");
  EXPECT_NEAR(limited.simulated_time, 0.5, 1e-9);
  EXPECT_EQ(limited.events.back().kind, "time-limit");

  nlohmann::json aborting = viscera::testing::expert_cavity_script();
  aborting["waypoints"][2]["abort"] = true;  // at t = 1.5 s
  const auto abort_script = ScriptedTrajectory::from_json(aborting, "abort");
  const SessionReport aborted = run(viscera::testing::cavity_scenario(), abort_script, 20.0);
  EXPECT_EQ(aborted.end_reason, "abort");
  EXPECT_NEAR(aborted.simulated_time, 1.5, 1e-3);
  EXPECT_EQ(task(aborted, "withdraw").status, "not-completed");
}

/// Every task of the sterilisation's tools is unavailable, its note saying `why`.
void expect_tool_tasks_unavailable(const SessionReport& report, const std::string& why) {
  for (const char* id :
       {"grasp-tube", "coagulate-isthmus", "clip-proximal", "clip-distal", "cut-tube"}) {
    EXPECT_EQ(task(report, id).status, "unavailable") << id;
    EXPECT_NE(task(report, id).note.find(why), std::string::npos) << task(report, id).note;
  }
}

TEST(SessionRunner, tasks_needing_tools_the_instrument_lacks_are_unavailable_with_the_reason) {
  core::Scenario scenario = viscera::testing::cavity_scenario();
  core::apply_procedure(scenario.session,
                        core::procedure_definition("laparoscopic-tubal-sterilisation"));
  const auto expert =
      ScriptedTrajectory::from_json(viscera::testing::expert_cavity_script(), "expert");
  // A hysteroscope has no working port for laparoscopic tools.
  scenario.session.instrument.kind = "hysteroscope";
  const SessionReport report = run(scenario, expert, 1.0);
  expect_tool_tasks_unavailable(report, "cannot simulate");
  // The fixture has no landmarks: the locating tasks say so instead of passing.
  EXPECT_EQ(task(report, "view-left-tube").status, "unavailable");
  EXPECT_NE(task(report, "view-left-tube").note.find("fallopian-tube-left"), std::string::npos);
  EXPECT_EQ(report.metrics.tasks_available(), 0);
  EXPECT_FALSE(report.laparoscopy.has_value());

  // The laparoscope's working port carries the tools: now only the missing site stops them.
  scenario.session.instrument.kind = "laparoscope";
  const SessionReport lap = run(scenario, expert, 1.0);
  expect_tool_tasks_unavailable(lap, "no landmark \"fallopian-tube-left\"");
  ASSERT_TRUE(lap.laparoscopy.has_value());
  EXPECT_TRUE(lap.laparoscopy->clips.empty());
}

TEST(SessionRunner, a_recorded_session_replays_bit_identically_and_a_nudge_departs) {
  const core::Scenario scenario = viscera::testing::cavity_scenario();
  const auto novice =
      ScriptedTrajectory::from_json(viscera::testing::novice_cavity_script(), "novice");
  const SessionReport recorded = run(scenario, novice, 6.0, true);
  ASSERT_GT(recorded.checkpoints.size(), 10u);
  const RecordedInput input(recorded.inputs);
  const SessionReport replayed = run(scenario, input, 6.0);
  EXPECT_EQ(replayed.checkpoints, recorded.checkpoints);
  EXPECT_EQ(replayed.final_state_hash, recorded.final_state_hash);
  // A micrometre on one step while the tool presses on the wall changes the state.
  auto nudged = recorded.inputs;
  std::size_t touching = 0;
  for (std::size_t i = 0; i < nudged.size(); ++i) {
    if (nudged[i].first >= 4400) {
      touching = i;
      break;
    }
  }
  nudged[touching].second.tip.x() += 1e-6;
  const RecordedInput nudged_input(nudged);
  EXPECT_NE(run(scenario, nudged_input, 6.0).final_state_hash, recorded.final_state_hash);
}

TEST(SessionRunner, surface_seen_counts_only_the_inspect_tasks_region) {
  // The camera circles outside the sphere, looking at its outer skin: with the procedure's
  // cavity task nothing it sees counts, without a task the whole surface does.
  const double far = viscera::testing::kCavityRadius + viscera::testing::kWallThickness + 0.012;
  std::vector<std::pair<double, std::pair<core::Vec3, core::Vec3>>> outside;
  for (int k = 0; k <= 4; ++k) {
    const double a = 1.5 * k;
    outside.push_back({0.5 * k, {{far * std::cos(a), far * std::sin(a), 0.0}, core::Vec3::Zero()}});
  }
  const auto script =
      ScriptedTrajectory::from_json(viscera::testing::cavity_script(outside), "outside");
  const core::Scenario with_task = viscera::testing::cavity_scenario();
  const SessionReport cavity_only = run(with_task, script, 2.0);
  EXPECT_EQ(cavity_only.metrics.contacts(), 0);
  EXPECT_EQ(cavity_only.metrics.surface_seen(), 0.0);
  EXPECT_EQ(task(cavity_only, "inspect-cavity").status, "not-completed");

  core::Scenario without_task = with_task;
  without_task.session.steps.clear();
  const SessionReport whole = run(without_task, script, 2.0);
  EXPECT_GT(whole.metrics.surface_seen(), 0.1);

  // A second inspect task on another region cannot be scored by the one camera region.
  core::Scenario two_regions = with_task;
  core::TaskSpec outer = two_regions.session.steps[1].substeps[0].tasks[0];
  outer.id = "inspect-outside";
  outer.parameters["region_value"] = 0;
  two_regions.session.steps[1].substeps[0].tasks.push_back(outer);
  const SessionReport report = run(two_regions, script, 0.2);
  EXPECT_EQ(task(report, "inspect-outside").status, "unavailable");
  EXPECT_NE(task(report, "inspect-outside").note.find("\"cavity\""), std::string::npos)
      << task(report, "inspect-outside").note;
}

}  // namespace
}  // namespace viscera::sim
