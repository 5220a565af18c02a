#include <gtest/gtest.h>

#include "core/error.h"
#include "simulator/session/headless_session.h"
#include "simulator/session/instrument_input.h"
#include "simulator/session/session_trace.h"
#include "tests/simulator/sim_fixtures.h"

namespace viscera::sim {
namespace {

/// A 4 × 4 × 2 cm block held at its base, top face at z = 2 cm.
core::Scenario block() {
  return viscera::testing::held_soft_block();
}

nlohmann::json script(const std::vector<std::pair<double, core::Vec3>>& waypoints) {
  nlohmann::json points = nlohmann::json::array();
  for (const auto& [t, tip] : waypoints)
    points.push_back({{"t", t}, {"tip", {tip.x(), tip.y(), tip.z()}}});
  return {{"format", "viscera-script"},
          {"version", 1},
          {"body", "block"},
          {"stiffness", 200.0},
          {"waypoints", points}};
}

SessionReport run_script(const ScriptedTrajectory& trajectory, bool record = false) {
  HeadlessRunOptions options;
  options.duration = trajectory.duration();
  options.instrument = &trajectory;
  options.instrument_body = trajectory.body();
  options.instrument_stiffness = trajectory.stiffness();
  options.record_inputs = record;
  return run_headless(block(), options);
}

TEST(ScriptedTrajectory, resolves_landmark_places_and_names_a_missing_landmark) {
  const std::vector<core::Landmark> marks = {
      {"os", "os", "block", core::Vec3(0.0, 0.0, 0.01), core::Vec3(0.0, 0.0, -1.0)},
      {"top", "top", "block", core::Vec3(0.0, 0.02, 0.05), core::Vec3::Zero()}};
  nlohmann::json s = script({{0.0, {0, 0, 0}}, {1.0, {0, 0, 0}}});
  s["waypoints"][0]["tip"] = {{"landmark", "os"}, {"along_normal", 0.008}};
  s["waypoints"][1]["tip"] = {
      {"landmark", "os"}, {"towards", "top"}, {"fraction", 0.5}, {"offset", {0.001, 0.0, 0.0}}};
  s["waypoints"][1]["look_at"] = {{"landmark", "top"}};
  const nlohmann::json resolved = resolve_script_landmarks(s, marks, "s.json");
  const auto trajectory = ScriptedTrajectory::from_json(resolved, "s.json", 30.0);
  // os + 8 mm along its outward normal (−z); then halfway to top, 1 mm to the side.
  EXPECT_TRUE(trajectory.tip(0, 0.0).isApprox(core::Vec3(0.0, 0.0, 0.002)));
  EXPECT_TRUE(trajectory.tip(0, 1.0).isApprox(core::Vec3(0.001, 0.01, 0.03)));
  const InstrumentState at_end = trajectory.state(0, 1.0);
  const core::Vec3 to_top = (core::Vec3(0.0, 0.02, 0.05) - at_end.tip).normalized();
  EXPECT_NEAR(view_direction(at_end, 30.0).dot(to_top), 1.0, 1e-9);
  EXPECT_TRUE(resolved["waypoints"][1]["look_at"].is_array());

  s["waypoints"][1]["look_at"] = {{"landmark", "fundus"}};
  try {
    resolve_script_landmarks(s, marks, "s.json");
    FAIL() << "an unknown landmark was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("s.json: /waypoints/1/look_at"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("\"fundus\""), std::string::npos) << e.what();
  }
}

TEST(ScriptedTrajectory, interpolates_between_waypoints_and_names_bad_ones) {
  const auto trajectory =
      ScriptedTrajectory::from_json(script({{0.0, {0, 0, 0.05}}, {1.0, {0, 0, 0.01}}}), "s.json");
  EXPECT_TRUE(trajectory.tip(0, 0.25).isApprox(core::Vec3(0, 0, 0.04)));
  EXPECT_TRUE(trajectory.tip(0, 7.0).isApprox(core::Vec3(0, 0, 0.01)));
  try {
    ScriptedTrajectory::from_json(script({{0.0, {0, 0, 0}}, {0.0, {0, 0, 1}}}), "s.json");
    FAIL() << "non-increasing times accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("s.json: /waypoints/1"), std::string::npos) << e.what();
  }
}

TEST(ScriptedTrajectory, holds_the_irrigation_valve_between_waypoints_and_refuses_other_values) {
  nlohmann::json json = {
      {"format", "viscera-script"},
      {"version", 2},
      {"waypoints",
       {{{"t", 0.0}, {"tip", {0, 0, 0.05}}, {"tool", "suction"}, {"irrigate", 1}},
        {{"t", 1.0}, {"tip", {0, 0, 0.04}}},
        {{"t", 2.0}, {"tip", {0, 0, 0.03}}, {"irrigate", 0}}}}};
  const auto trajectory = ScriptedTrajectory::from_json(json, "s.json");
  EXPECT_TRUE(trajectory.state(0, 0.0).irrigating);
  EXPECT_TRUE(trajectory.state(0, 1.5).irrigating);  // held until a waypoint changes it
  EXPECT_FALSE(trajectory.state(0, 2.0).irrigating);
  EXPECT_EQ(trajectory.state(0, 1.5).tool, LaparoscopicTool::Suction);
  json["waypoints"][1]["irrigate"] = 2;
  try {
    ScriptedTrajectory::from_json(json, "s.json");
    FAIL() << "irrigate 2 accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("s.json: /waypoints/1/irrigate"), std::string::npos)
        << e.what();
  }
}

TEST(ScriptedSession, expert_and_novice_separate_on_every_metric) {
  const core::Vec3 above(0.021, 0.019, 0.04), target(0.021, 0.019, 0.016);
  // Expert: straight down to 4 mm depth, hold, straight back out.
  const auto expert = ScriptedTrajectory::from_json(
      script({{0.0, above}, {0.4, target}, {0.6, target}, {1.0, above}}), "e");
  // Novice: wanders, prods three times, presses deeper.
  const auto novice = ScriptedTrajectory::from_json(script({{0.0, above + core::Vec3(0.01, 0, 0)},
                                                            {0.15, {0.03, 0.01, 0.013}},
                                                            {0.3, {0.01, 0.03, 0.03}},
                                                            {0.45, {0.012, 0.025, 0.012}},
                                                            {0.6, {0.03, 0.03, 0.03}},
                                                            {0.75, {0.025, 0.012, 0.011}},
                                                            {1.0, above}}),
                                                    "n");
  const SessionReport e = run_script(expert), n = run_script(novice);
  ASSERT_TRUE(e.has_instrument && n.has_instrument);
  EXPECT_LT(e.metrics.path_length(), n.metrics.path_length());
  EXPECT_LT(e.metrics.contacts(), n.metrics.contacts());
  EXPECT_LT(e.metrics.max_force(), n.metrics.max_force());
  EXPECT_GT(e.metrics.contact_time(), 0.0);
  EXPECT_EQ(e.metrics.contacts(), 1);
  EXPECT_GE(n.metrics.contacts(), 3);
  // Economy over the in-and-out path is low for both; the straight half-path is economical.
  const auto in_only = ScriptedTrajectory::from_json(script({{0.0, above}, {0.4, target}}), "i");
  EXPECT_NEAR(run_script(in_only).metrics.economy(), 1.0, 1e-9);
}

TEST(ScriptedSession, recorded_tips_replay_to_the_same_checkpoints) {
  const core::Vec3 above(0.021, 0.019, 0.04), target(0.021, 0.019, 0.015);
  const auto trajectory =
      ScriptedTrajectory::from_json(script({{0.0, above}, {0.3, target}, {0.5, above}}), "s");
  const SessionReport recorded = run_script(trajectory, true);
  // Moving every step: one recorded change per step, from step 0.
  ASSERT_EQ(recorded.inputs.size(), static_cast<std::size_t>(recorded.steps + 1));
  EXPECT_EQ(recorded.inputs.back().first, recorded.steps);
  ASSERT_FALSE(recorded.checkpoints.empty());
  const RecordedInput input(recorded.inputs);
  HeadlessRunOptions options;
  options.duration = trajectory.duration();
  options.instrument = &input;
  options.instrument_body = "block";
  options.instrument_stiffness = trajectory.stiffness();
  const SessionReport replayed = run_headless(block(), options);
  EXPECT_EQ(replayed.checkpoints, recorded.checkpoints);
  EXPECT_EQ(replayed.final_state_hash, recorded.final_state_hash);
  // A nanometre on one tip during contact changes the state.
  auto nudged = recorded.inputs;
  nudged[250].second.tip.z() += 1e-9;
  const RecordedInput nudged_input(nudged);
  options.instrument = &nudged_input;
  EXPECT_NE(run_headless(block(), options).final_state_hash, recorded.final_state_hash);
}

TEST(SessionTrace, round_trips_through_json_exactly) {
  SessionTrace trace;
  trace.package = "/tmp/p.vscene";
  trace.manifest_sha256 = std::string(64, 'a');
  trace.duration = 1.5;
  trace.body = "ball";
  trace.stiffness = 200.0;
  trace.checkpoint_interval = 100;
  InstrumentState a, b;
  a.tip = {0.1, 0.2, 0.30000000000000004};
  b.tip = {1e-17, -3.0, 2.5};
  b.axis = core::Vec3(1.0, 2.0, 3.0).normalized();
  b.inflow = 0.3;
  b.abort = true;
  b.electrode = true;
  b.loop_extension = 0.004;
  b.coagulation = true;
  b.tool = LaparoscopicTool::Suction;
  b.jaws_closed = true;
  b.irrigating = true;
  b.follow = 0.25;
  b.anchor = {0.01, -0.02, 0.030000000000000002};
  b.anchor_body = "polyp-1";
  b.second.inserted = true;
  b.second.tip = {0.02, -0.01, 0.07000000000000001};
  b.second.axis = core::Vec3(-1.0, 0.5, 2.0).normalized();
  b.second.tool = LaparoscopicTool::Hook;
  b.second.jaws_closed = true;
  b.second.electrode = true;
  b.camera.held = true;
  b.camera.tip = {0.0, -0.07, 0.07500000000000001};
  b.camera.axis = core::Vec3(0.1, 1.0, -0.2).normalized();
  b.camera.up = b.camera.axis.unitOrthogonal();
  trace.inputs = {{0, a}, {17, b}};
  trace.checkpoints = {{100, "x"}, {200, "y"}};
  trace.final_state_hash = "z";
  const SessionTrace back =
      trace_from_json(nlohmann::json::parse(trace_to_json(trace).dump()), "t.json");
  EXPECT_EQ(back.inputs, trace.inputs);
  EXPECT_EQ(back.input()->state(16, 0.0), a);
  EXPECT_EQ(back.input()->state(17, 0.0), b);
  EXPECT_EQ(back.checkpoints, trace.checkpoints);
  EXPECT_EQ(back.manifest_sha256, trace.manifest_sha256);
  // A trace from before the irrigation valve (12 members per input) reads with the valve shut.
  nlohmann::json older = trace_to_json(trace);
  while (older["inputs"][1].size() > 12)
    older["inputs"][1].erase(12);
  const SessionTrace old_back = trace_from_json(older, "t.json");
  EXPECT_FALSE(old_back.inputs[1].second.irrigating);
  EXPECT_TRUE(old_back.inputs[1].second.jaws_closed);
  // One from before tips followed the tissue (13 members) reads with a tip that does not.
  nlohmann::json unfollowed = trace_to_json(trace);
  while (unfollowed["inputs"][1].size() > 13)
    unfollowed["inputs"][1].erase(13);
  EXPECT_EQ(trace_from_json(unfollowed, "t.json").inputs[1].second.follow, 0.0);
  // One from before the laparoscope was held apart (17 members) reads with the optics at the
  // working port.
  nlohmann::json one_camera = trace_to_json(trace);
  one_camera["inputs"][1].erase(17);
  EXPECT_FALSE(trace_from_json(one_camera, "t.json").inputs[1].second.camera.held);
  nlohmann::json broken = trace_to_json(trace);
  broken.erase("inputs");
  EXPECT_THROW(trace_from_json(broken, "t.json"), core::ValidationError);
  // A step number no integer holds is refused, not cast (undefined behaviour).
  for (const char* member : {"inputs", "checkpoints"}) {
    nlohmann::json huge = trace_to_json(trace);
    huge[member][1][0] = 1e300;
    try {
      (void)trace_from_json(huge, "t.json");
      ADD_FAILURE() << member << ": a step of 1e300 accepted";
    } catch (const core::ValidationError& e) {
      EXPECT_EQ(e.location().json_pointer, std::string("/") + member);
    }
  }
}

}  // namespace
}  // namespace viscera::sim
