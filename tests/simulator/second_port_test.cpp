// The second instrument port of a laparoscopic session (issue 19 §3: two instrument ports
// beside the laparoscope): the left hand's tool in scripts (held, blended, withdrawn, bad
// members named), its own contact with the tissue, its own grasper, and its path.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "core/error.h"
#include "simulator/session/headless_session.h"
#include "simulator/session/instrument_input.h"
#include "simulator/session/session_runner.h"
#include "simulator/world/world.h"
#include "tests/simulator/left_tube_patient.h"
#include "tests/simulator/script_json.h"

namespace viscera::sim {
namespace {

using testing::left_tube_patient;

using testing::input_error;
using testing::script;

TEST(SecondPort, a_script_puts_a_tool_in_blends_its_pose_holds_its_switches_and_withdraws_it) {
  const auto trajectory = ScriptedTrajectory::from_json(
      script(
          {{{"t", 0.0}, {"tip", {0, 0, 0.05}}},
           {{"t", 1.0},
            {"tip", {0, 0, 0.05}},
            {"left", {{"tip", {0.02, 0, 0.04}}, {"axis", {0, 0, -2}}, {"tool", "grasper"}}}},
           {{"t", 2.0}, {"tip", {0, 0, 0.05}}, {"left", {{"tip", {0.02, 0, 0.02}}, {"close", 1}}}},
           {{"t", 3.0}, {"tip", {0, 0, 0.05}}},
           {{"t", 4.0}, {"tip", {0, 0, 0.05}}, {"left", {{"withdraw", true}}}}}),
      "s.json");
  EXPECT_FALSE(trajectory.state(0, 0.5).second.inserted);  // empty until its waypoint
  const InstrumentState in = trajectory.state(0, 1.0);
  ASSERT_TRUE(in.second.inserted);
  EXPECT_EQ(in.second.tool, LaparoscopicTool::Grasper);
  EXPECT_EQ(in.second.axis, core::Vec3(0, 0, -1));  // made unit
  EXPECT_NEAR(in.second.up.dot(in.second.axis), 0.0, 1e-15);
  const InstrumentState half = trajectory.state(0, 1.5);
  EXPECT_NEAR(half.second.tip.z(), 0.03, 1e-12);  // the pose blends
  EXPECT_FALSE(half.second.jaws_closed);          // the jaws switch at their waypoint
  EXPECT_TRUE(trajectory.state(0, 2.0).second.jaws_closed);
  EXPECT_TRUE(trajectory.state(0, 3.5).second.jaws_closed);  // held
  EXPECT_FALSE(trajectory.state(0, 4.0).second.inserted);
  // The working port is untouched by the second's members.
  EXPECT_EQ(trajectory.state(0, 2.0).tool, LaparoscopicTool::None);
  EXPECT_FALSE(trajectory.state(0, 2.0).jaws_closed);
  const InstrumentState port = in_port(trajectory.state(0, 2.0), 1);
  EXPECT_EQ(port.tip, core::Vec3(0.02, 0, 0.02));
  EXPECT_TRUE(port.jaws_closed);
  EXPECT_EQ(port.tool, LaparoscopicTool::Grasper);
}

TEST(SecondPort, a_bad_second_port_member_is_named_with_its_place) {
  EXPECT_NE(input_error(script({{{"t", 0.0}, {"tip", {0, 0, 0}}, {"left", {{"tool", "grasper"}}}}}))
                .find("s.json: /waypoints/0/left: a tool put into the second port needs a"),
            std::string::npos);
  EXPECT_NE(
      input_error(
          script({{{"t", 0.0}, {"tip", {0, 0, 0}}, {"left", {{"tip", {0, 0, 0}}, {"close", 2}}}}}))
          .find("s.json: /waypoints/0/left/close: close must be 0 or 1"),
      std::string::npos);
  EXPECT_NE(input_error(script({{{"t", 0.0},
                                 {"tip", {0, 0, 0}},
                                 {"left", {{"tip", {0, 0, 0}}, {"tool", "stapler"}}}}}))
                .find("s.json: /waypoints/0/left/tool: tool must be one of"),
            std::string::npos);
  EXPECT_NE(input_error(script({{{"t", 0.0}, {"tip", {0, 0, 0}}, {"left", 3}}}))
                .find("s.json: /waypoints/0/left: the second port's tool must be an object"),
            std::string::npos);
}

/// The left tube's isthmus where it hangs at the session's start (m), and directions there:
/// the tube's length (towards the uterus), the view from the front (into the body) and across.
struct Isthmus {
  core::Vec3 point, along, into, across;
};

Isthmus isthmus() {
  const auto& marks = left_tube_patient().landmarks;
  const auto it = std::find_if(marks.begin(), marks.end(),
                               [](const auto& l) { return l.id == "fallopian-tube-left"; });
  Isthmus i;
  i.point = testing::settled_left_isthmus();
  i.into = -it->normal;
  // The template's left tube runs out from the cornu along +x, rising 1 in 3 over its first
  // segment.
  i.along = -core::Vec3(1.0, 0.0, 1.0 / 3.0).normalized();
  i.across = i.into.cross(i.along).normalized();
  return i;
}

/// The laparoscope held 5 cm off the isthmus and the second port's tool following `left`
/// (its members by time).
ScriptedTrajectory two_handed(const std::vector<std::pair<double, nlohmann::json>>& left) {
  const Isthmus i = isthmus();
  const core::Vec3 camera = i.point - 0.05 * i.into;
  nlohmann::json waypoints = nlohmann::json::array();
  for (const auto& [t, port] : left)
    waypoints.push_back({{"t", t}, {"tip", camera}, {"axis", i.into}, {"left", port}});
  return ScriptedTrajectory::from_json(script(waypoints), "two-handed", 30.0);
}

HeadlessRunOptions on_the_tube(const InstrumentInput& input, double duration) {
  HeadlessRunOptions options;
  options.duration = duration;
  options.instrument = &input;
  options.instrument_body = "tube-left";
  options.end_when_complete = false;
  return options;
}

/// The session stepped to its end; returns the runner for its world and forces.
void run(SessionRunner& runner, const InstrumentInput& input) {
  while (!runner.finished()) {
    const long long next = runner.world().steps() + 1;
    runner.step(input.state(next, static_cast<double>(next) * runner.world().time_step()));
  }
}

/// Largest distance between the tube's knots in two worlds, m.
double tube_difference(const World& a, const World& b) {
  const int tube = a.body_index("tube-left");
  const auto x = a.state().range(a.state().positions, tube);
  const auto y = b.state().range(b.state().positions, tube);
  double largest = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k)
    largest = std::max(largest, (x[k] - y[k]).norm());
  return largest;
}

TEST(SecondPort, its_probe_pushes_the_tube_through_a_contact_of_its_own) {
  const Isthmus i = isthmus();
  const core::Vec3 above = i.point - 0.02 * i.into, pressed = i.point + 0.003 * i.into;
  const auto probe = [&](const core::Vec3& tip) {
    return nlohmann::json{{"tip", tip}, {"axis", i.into}, {"up", i.across}, {"tool", "none"}};
  };
  // The probe, in from above the isthmus, pressed 3 mm past the tube's front; and held above.
  const auto pressing =
      two_handed({{0.0, probe(above)}, {0.4, probe(pressed)}, {1.0, probe(pressed)}});
  const auto hovering = two_handed({{0.0, probe(above)}, {1.0, probe(above)}});
  SessionRunner pressed_in(left_tube_patient(), on_the_tube(pressing, 1.0));
  SessionRunner beside(left_tube_patient(), on_the_tube(hovering, 1.0));
  run(pressed_in, pressing);
  run(beside, hovering);
  // The tube gives way by millimetres under the probe, which feels it push back.
  EXPECT_GT(tube_difference(pressed_in.world(), beside.world()), 1e-3);
  EXPECT_GT(pressed_in.second_port_force().norm(), 1e-4);      // the soft tube gives way: ~0.7 mN
  EXPECT_LT(pressed_in.second_port_force().dot(i.into), 0.0);  // back towards the port
  EXPECT_EQ(beside.second_port_force(), core::Vec3::Zero());
  EXPECT_EQ(pressed_in.instrument_force(), core::Vec3::Zero());  // the right hand is free
  const SessionReport report = pressed_in.finish();
  ASSERT_TRUE(report.laparoscopy.has_value());
  // The path counts from the first step on (the first millisecond's 0.05 mm before it).
  EXPECT_NEAR(report.laparoscopy->path_per_hand.at("left"), (pressed - above).norm(), 1e-4);
  EXPECT_LT(report.laparoscopy->path_per_hand.at("right"), 1e-12);
}

TEST(SecondPort, its_grasper_holds_and_moves_the_tube_and_lets_go_when_withdrawn) {
  const Isthmus i = isthmus();
  // The jaws across the tube 8.5 mm lateral of the isthmus, its centre 8 mm behind the tip.
  const core::Vec3 grip = i.point - 0.0085 * i.along;
  const core::Vec3 tip = grip + 0.008 * i.into;
  const auto grasper = [&](const core::Vec3& at, int close) {
    return nlohmann::json{
        {"tip", at}, {"axis", i.into}, {"up", i.across}, {"tool", "grasper"}, {"close", close}};
  };
  const core::Vec3 lifted = tip - 0.002 * i.into;  // drawn 2 mm towards the camera
  const auto input = two_handed({{0.0, grasper(tip - 0.03 * i.into, 0)},
                                 {0.4, grasper(tip, 0)},
                                 {0.5, grasper(tip, 1)},
                                 {0.9, grasper(lifted, 1)},
                                 {1.2, grasper(lifted, 1)},
                                 {1.3, {{"withdraw", true}}}});
  SessionRunner runner(left_tube_patient(), on_the_tube(input, 1.5));
  const auto still = two_handed({{0.0, grasper(tip - 0.03 * i.into, 0)}});
  SessionRunner untouched(left_tube_patient(), on_the_tube(still, 1.2));
  while (runner.world().time() < 1.2 - 1e-9) {
    const long long next = runner.world().steps() + 1;
    runner.step(input.state(next, static_cast<double>(next) * runner.world().time_step()));
  }
  run(untouched, still);
  // Held and drawn 2 mm, the tube came along by about that much.
  EXPECT_GT(tube_difference(runner.world(), untouched.world()), 1e-3);
  EXPECT_GT(runner.second_port_force().norm(), 0.0);
  run(runner, input);
  const SessionReport r = runner.finish();
  ASSERT_TRUE(r.laparoscopy.has_value());
  EXPECT_EQ(r.laparoscopy->grasps, 1);
  EXPECT_GT(r.laparoscopy->max_grasp_force, 0.0);
  const auto count = [&](const std::string& kind) {
    return std::count_if(r.events.begin(), r.events.end(),
                         [&](const auto& e) { return e.kind == kind; });
  };
  EXPECT_EQ(count("tool-inserted"), 1);
  EXPECT_EQ(count("grasp"), 1);
  EXPECT_EQ(count("grasp-released"), 1);  // taken out of the port, it lets go
  EXPECT_EQ(count("tool-withdrawn"), 1);
  EXPECT_NEAR(r.laparoscopy->path_per_hand.at("left"), 0.03 + 0.002, 1e-4);
}

}  // namespace
}  // namespace viscera::sim
