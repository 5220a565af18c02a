// The laparoscope held as a camera apart from the working port (issue 19 §3: two instrument
// ports plus the laparoscope as camera): a script takes it up and aims it, blends it and gives
// it back; bad members are named; the keyboard moves it without moving a tool; and a session
// centres its targets and steams its lens where the camera is, not where the tool is.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"
#include "simulator/session/headless_session.h"
#include "simulator/session/instrument_input.h"
#include "simulator/session/manual_control.h"
#include "tests/simulator/left_tube_patient.h"
#include "tests/simulator/script_json.h"

namespace viscera::sim {
namespace {

using testing::left_tube_patient;

using testing::input_error;
using testing::script;

double angle_between(const core::Vec3& a, const core::Vec3& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
}

TEST(LaparoscopeCamera, a_script_holds_it_from_the_start_aims_it_blends_it_and_gives_it_back) {
  const core::Vec3 target(0.0, 0.0, 0.0), other(0.04, 0.0, 0.0);
  const auto trajectory = ScriptedTrajectory::from_json(
      script({{{"t", 0.0}, {"tip", {0, 0, 0.05}}},
              {{"t", 1.0},
               {"tip", {0, 0, 0.05}},
               {"camera", {{"tip", {0, -0.06, 0.02}}, {"look_at", target}}}},
              {{"t", 2.0}, {"tip", {0, 0, 0.05}}, {"camera", {{"look_at", other}}}},
              {{"t", 3.0}, {"tip", {0.01, 0, 0.05}}, {"camera", {{"release", true}}}}}),
      "s.json", 30.0);
  // The first camera given holds from t = 0, aimed through the 30° optics at its target.
  for (const double t : {0.0, 1.0}) {
    const InstrumentState s = trajectory.state(0, t);
    ASSERT_TRUE(s.camera.held) << t;
    const InstrumentState optics = camera_pose(s);
    EXPECT_EQ(optics.tip, core::Vec3(0, -0.06, 0.02));
    EXPECT_LT(angle_between(view_direction(optics, 30.0), target - optics.tip), 1e-9);
    EXPECT_NEAR(angle_between(optics.axis, view_direction(optics, 30.0)), std::numbers::pi / 6,
                1e-9);
    // The picture's up is +z as far as the line of sight allows (a level horizon).
    const core::Vec3 view = view_direction(optics, 30.0);
    const core::Vec3 level = (core::Vec3::UnitZ() - view.dot(core::Vec3::UnitZ()) * view);
    EXPECT_LT(angle_between(optics.up - optics.up.dot(view) * view, level), 1e-9);
  }
  // Halfway to the next aim the view has turned part of the way; at the waypoint it is there.
  const InstrumentState half = camera_pose(trajectory.state(0, 1.5));
  const double swing = angle_between(target - half.tip, other - half.tip);
  const double turned = angle_between(target - half.tip, view_direction(half, 30.0));
  EXPECT_GT(turned, 0.3 * swing);
  EXPECT_LT(turned, 0.7 * swing);
  const InstrumentState there = camera_pose(trajectory.state(0, 2.0));
  EXPECT_LT(angle_between(view_direction(there, 30.0), other - there.tip), 1e-9);
  // Given back, the optics are the working port's again — at its waypoint, not before.
  EXPECT_TRUE(trajectory.state(0, 2.9).camera.held);
  const InstrumentState released = trajectory.state(0, 3.0);
  EXPECT_FALSE(released.camera.held);
  EXPECT_EQ(camera_pose(released).tip, released.tip);
  // Without a camera the optics are the instrument's own.
  const InstrumentState plain =
      ScriptedTrajectory::from_json(script({{{"t", 0.0}, {"tip", {0, 0, 0.05}}}}), "s.json")
          .state(0, 0.0);
  EXPECT_FALSE(plain.camera.held);
  EXPECT_EQ(camera_pose(plain).axis, plain.axis);
}

TEST(LaparoscopeCamera, a_bad_camera_member_is_named_with_its_place) {
  EXPECT_NE(
      input_error(script({{{"t", 0.0}, {"tip", {0, 0, 0}}, {"camera", {{"look_at", {0, 0, 1}}}}}}))
          .find("s.json: /waypoints/0/camera: a laparoscope taken up as the camera needs a"),
      std::string::npos);
  EXPECT_NE(input_error(script({{{"t", 0.0}, {"tip", {0, 0, 0}}, {"camera", "umbilicus"}}}))
                .find("s.json: /waypoints/0/camera: the camera must be an object"),
            std::string::npos);
  EXPECT_NE(input_error(script({{{"t", 0.0},
                                 {"tip", {0, 0, 0}},
                                 {"camera", {{"tip", {0, 0, 0}}, {"axis", {0, 0, 0}}}}}}))
                .find("s.json: /waypoints/0/camera: the camera's tip and axis must be finite"),
            std::string::npos);
  EXPECT_NE(input_error(script({{{"t", 0.0}, {"tip", {0, 0, 0}}, {"camera", {{"tip", "up"}}}}}))
                .find("s.json: /waypoints/0/camera: the camera's tip, axis, up and look_at are"),
            std::string::npos);
}

TEST(LaparoscopeCamera, the_keyboard_takes_it_up_where_the_optics_are_and_moves_it_alone) {
  InstrumentState start;
  start.tip = {0.0, 0.0, 0.05};
  start.axis = {0.0, 0.0, -1.0};
  start.up = {0.0, 1.0, 0.0};
  ManualControl control(start);
  control.press(ManualCommand::TakeCamera);
  EXPECT_EQ(control.hand(), 2);
  ASSERT_TRUE(control.state().camera.held);
  EXPECT_EQ(camera_pose(control.state()).tip, start.tip);  // the view does not jump
  control.press(ManualCommand::Advance);
  control.advance(1.0);
  control.release(ManualCommand::Advance);
  // The camera went 1 cm down its shaft; the tool stayed.
  EXPECT_NEAR((control.state().camera.tip - core::Vec3(0.0, 0.0, 0.04)).norm(), 0.0, 1e-12);
  EXPECT_EQ(control.state().tip, start.tip);
  // The switches still act on the tool last moved (the right hand's).
  control.press(ManualCommand::ToolGrasper);
  EXPECT_EQ(control.state().tool, LaparoscopicTool::Grasper);
  // Tab goes back to the right hand; the camera stays where it was put.
  control.press(ManualCommand::SwitchHand);
  EXPECT_EQ(control.hand(), 0);
  control.press(ManualCommand::Advance);
  control.advance(1.0);
  EXPECT_NEAR(control.state().tip.z(), 0.04, 1e-12);
  EXPECT_NEAR(control.state().camera.tip.z(), 0.04, 1e-12);
  EXPECT_EQ(ManualControl::command_for_key("v"), ManualCommand::TakeCamera);
}

/// The left isthmus of the one-tube patient.
const core::Landmark& left_isthmus() {
  const auto& marks = left_tube_patient().landmarks;
  return *std::find_if(marks.begin(), marks.end(),
                       [](const auto& l) { return l.id == "fallopian-tube-left"; });
}

SessionReport run(const ScriptedTrajectory& input) {
  HeadlessRunOptions options;
  options.duration = input.duration();
  options.instrument = &input;
  options.instrument_body = "tube-left";
  options.end_when_complete = false;
  return run_headless(left_tube_patient(), options);
}

const TaskResult& task(const SessionReport& r, const std::string& id) {
  return *std::find_if(r.tasks.begin(), r.tasks.end(), [&](const auto& t) { return t.id == id; });
}

TEST(LaparoscopeCamera, the_tube_is_centred_by_the_camera_even_with_the_tool_turned_away) {
  const core::Landmark& isthmus = left_isthmus();
  // The working port's tool 5 cm in front of the isthmus, looking away from it (along the tube's
  // normal, out of the body).
  const core::Vec3 tool = isthmus.position + 0.05 * isthmus.normal;
  const nlohmann::json away = {{"tip", tool}, {"axis", isthmus.normal}};
  // The camera 8 cm off the isthmus, half-way round to the side, aimed at it; and aimed 30°
  // beside it.
  const core::Vec3 eye =
      isthmus.position + 0.08 * (isthmus.normal + core::Vec3(-1.0, 0.0, 0.0)).normalized();
  const core::Vec3 beside =
      isthmus.position + 0.08 * 0.6 * core::Vec3(0.0, 0.0, 1.0);  // 25° off its centre
  const auto session = [&](const core::Vec3& aim, bool camera) {
    nlohmann::json first = away, last = away;
    first["t"] = 0.0;
    last["t"] = 1.5;
    last["tip"] = tool + core::Vec3(0.0, 0.0, 0.001);  // the trainee moves
    if (camera) first["camera"] = {{"tip", eye}, {"look_at", aim}};
    return run(ScriptedTrajectory::from_json(script({first, last}), "s.json", 30.0));
  };
  EXPECT_EQ(task(session(isthmus.position, true), "view-left-tube").status, "completed");
  EXPECT_EQ(task(session(beside, true), "view-left-tube").status, "not-completed");
  EXPECT_EQ(task(session(isthmus.position, false), "view-left-tube").status, "not-completed");
}

TEST(LaparoscopeCamera, the_lens_that_steams_is_the_cameras) {
  const core::Landmark& isthmus = left_isthmus();
  const core::Vec3 into = -isthmus.normal;
  const core::Vec3 across = into.cross(core::Vec3(1.0, 0.0, 1.0 / 3.0).normalized()).normalized();
  // Bipolar forceps across the isthmus, coagulating for a second with the jaws closed.
  const core::Vec3 bite = isthmus.position + 0.006 * into;
  const auto coagulation = [&](const nlohmann::json& camera) {
    nlohmann::json w0 = {{"t", 0.0},
                         {"tip", bite - 0.02 * into},
                         {"axis", into},
                         {"up", across},
                         {"tool", "bipolar"}};
    nlohmann::json w1 = {{"t", 0.4}, {"tip", bite}};
    nlohmann::json w2 = {{"t", 0.5}, {"tip", bite}, {"close", 1}, {"coagulate", 1}};
    nlohmann::json w3 = {{"t", 1.6}, {"tip", bite}, {"close", 0}, {"coagulate", 0}};
    if (!camera.is_null()) w0["camera"] = camera;
    return run(ScriptedTrajectory::from_json(script({w0, w1, w2, w3}), "s.json", 30.0));
  };
  // The operating laparoscope's lens is at the bite; a camera 8 cm back stays clear; one 2 cm
  // off the bite steams as the operating laparoscope does.
  const SessionReport at_tool = coagulation(nullptr);
  const SessionReport far = coagulation(
      {{"tip", isthmus.position + 0.08 * isthmus.normal}, {"look_at", isthmus.position}});
  const SessionReport close = coagulation(
      {{"tip", isthmus.position + 0.02 * isthmus.normal}, {"look_at", isthmus.position}});
  ASSERT_TRUE(at_tool.laparoscopy && far.laparoscopy && close.laparoscopy);
  EXPECT_GT(at_tool.laparoscopy->coagulation_time, 0.5);
  EXPECT_GT(at_tool.laparoscopy->peak_lens_fog, 0.1);
  EXPECT_LT(far.laparoscopy->peak_lens_fog, 0.1 * at_tool.laparoscopy->peak_lens_fog);
  EXPECT_GT(close.laparoscopy->peak_lens_fog, 0.5 * at_tool.laparoscopy->peak_lens_fog);
  // The smoke rises the same wherever the camera is.
  EXPECT_EQ(far.laparoscopy->smoke_puffs, at_tool.laparoscopy->smoke_puffs);
}

}  // namespace
}  // namespace viscera::sim
