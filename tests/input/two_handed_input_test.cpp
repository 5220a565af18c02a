// The second instrument port's haptic device (issue 19 §3/§7): poses of a left-hand device on a
// real UDP socket (loopback) put a tool into the second port of a headless laparoscopy session,
// close its jaws and take it out again, and the tissue's force on that tool comes back to it.

#include "simulator/input/two_handed_input.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <mutex>
#include <thread>

#include "simulator/haptics/simulated_device.h"
#include "simulator/input/live_session.h"
#include "simulator/session/headless_session.h"
#include "simulator/session/session_runner.h"
#include "simulator/world/world.h"
#include "tests/simulator/left_tube_patient.h"

namespace viscera::sim {
namespace {

using testing::left_tube_patient;

TEST(SecondPortFromPose, a_pose_puts_the_tool_in_and_the_withdrawn_bit_takes_it_out) {
  DevicePose pose;
  pose.position = {0.01, 0.02, 0.03};
  const double half = 0.5 * 1.2;  // 1.2 rad about x
  pose.orientation = {std::cos(half), std::sin(half), 0.0, 0.0};
  pose.buttons = kDeviceJawsClosed | kDeviceCoagulationPedal | (4U << kDeviceToolShift);
  const SecondPort in = second_port_from_pose(pose, SecondPort{});
  const InstrumentState same = instrument_from_pose(pose);
  EXPECT_TRUE(in.inserted);
  EXPECT_EQ(in.tip, pose.position);
  EXPECT_EQ(in.axis, same.axis);
  EXPECT_EQ(in.up, same.up);
  EXPECT_EQ(in.tool, LaparoscopicTool::Bipolar);
  EXPECT_TRUE(in.jaws_closed);
  EXPECT_TRUE(in.coagulation);
  EXPECT_FALSE(in.electrode);
  EXPECT_FALSE(in.irrigating);
  // Tool bits 7 keep the tool; the other bits still count.
  pose.buttons = kDeviceIrrigating | (kDeviceToolUnchanged << kDeviceToolShift);
  const SecondPort kept = second_port_from_pose(pose, in);
  EXPECT_EQ(kept.tool, LaparoscopicTool::Bipolar);
  EXPECT_FALSE(kept.jaws_closed);
  EXPECT_TRUE(kept.irrigating);
  // Withdrawn: the port is empty whatever else the pose says.
  pose.buttons = kDeviceWithdrawn | kDeviceJawsClosed | (1U << kDeviceToolShift);
  EXPECT_EQ(second_port_from_pose(pose, in), SecondPort{});
  // The bit is apart from every other.
  EXPECT_EQ(kDeviceWithdrawn & (kDeviceToolMask | kDeviceJawsClosed | kDeviceAbortButton |
                                kDeviceCuttingPedal | kDeviceCoagulationPedal | kDeviceIrrigating),
            0U);
}

/// The left tube's isthmus where it hangs once the patient has settled (m), and the direction
/// from the front into the body there.
struct Isthmus {
  core::Vec3 point, into;
};

Isthmus isthmus() {
  const auto& marks = left_tube_patient().landmarks;
  const auto it = std::find_if(marks.begin(), marks.end(),
                               [](const auto& l) { return l.id == "fallopian-tube-left"; });
  return {testing::settled_left_isthmus(), -it->normal};
}

/// The right hand holding the laparoscope still (the working port's input of these tests).
class StillLaparoscope final : public LiveInput {
 public:
  explicit StillLaparoscope(const InstrumentState& state) : state_(state) {}
  InstrumentState next(double) override { return state_; }
  const InstrumentState& current() const override { return state_; }
  std::string describe() const override { return "a still laparoscope"; }

 private:
  InstrumentState state_;
};

/// What the left device saw of one phase of the session: feedback forces, N.
struct Phase {
  int packets = 0;
  core::Vec3 strongest = core::Vec3::Zero();
};

TEST(TwoHandedInput, a_left_device_on_loopback_drives_the_second_port_and_feels_the_tube) {
  const Isthmus i = isthmus();
  InstrumentState camera;
  camera.tip = i.point - 0.05 * i.into;
  camera.axis = i.into;
  orthonormalise(camera);
  // The soft tube pushes back with about a millinewton: below the hysteroscopy device's
  // smallest renderable force (DeviceLimits::min_force, sent as zero), so this device renders all.
  DeviceLimits limits;
  limits.min_force = 0.0;
  TwoHandedInput input(std::make_unique<StillLaparoscope>(camera), {"127.0.0.1", 0}, limits);
  EXPECT_FALSE(input.current().second.inserted) << "empty until the left device speaks";
  HeadlessRunOptions options;
  options.duration = 1.2;
  options.record_inputs = true;
  options.instrument_body = "tube-left";
  options.end_when_complete = false;

  // The device's phases by the simulated time its feedback echoes: a probe in from 2 cm above
  // the tube and pressed 3 mm past its front and back (0–0.6 s), a grasper with its jaws closed
  // held clear above (0.6–0.9 s), then the tool out (from 0.9 s).
  const core::Vec3 above = i.point - 0.02 * i.into, pressed = i.point + 0.003 * i.into;
  const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(core::Vec3::UnitZ(), i.into);
  std::atomic<bool> done{false};
  std::mutex mutex;
  Phase probing, pressing, grasping, withdrawn;
  std::thread device([&] {
    SimulatedDevice client(input.left_port());
    double t = 0.0;  // s, the session's time as the last feedback told it
    DevicePose pose;
    pose.orientation = {q.w(), q.x(), q.y(), q.z()};
    for (std::uint32_t n = 1; !done.load(); ++n) {
      pose.sequence = n;
      if (t < 0.6) {
        // In over 0.3 s, held pressed to 0.5 s, drawn back out by 0.6 s (no jump in contact).
        if (t < 0.3)
          pose.position = above + (t / 0.3) * (pressed - above);
        else if (t < 0.5)
          pose.position = pressed;
        else
          pose.position = pressed + std::min(1.0, (t - 0.5) / 0.09) * (above - pressed);
        pose.buttons = 0U << kDeviceToolShift;  // no tool: the blunt probe
      } else if (t < 0.9) {
        pose.position = above;
        pose.buttons = (1U << kDeviceToolShift) | kDeviceJawsClosed;
      } else {
        pose.position = above;
        pose.buttons = kDeviceWithdrawn;
      }
      client.send(pose);
      for (auto feedback = client.receive(1); feedback; feedback = client.receive(0)) {
        t = static_cast<double>(feedback->time_ns) * 1e-9;
        // Pressing: the probe held 3 mm in (0.35–0.5 s, after the first packets that answer it).
        Phase& phase = t >= 0.35 && t < 0.5 ? pressing
                       : t < 0.6            ? probing
                       : t < 0.9            ? grasping
                                            : withdrawn;
        const std::lock_guard<std::mutex> lock(mutex);
        ++phase.packets;
        if (feedback->force.norm() > phase.strongest.norm()) phase.strongest = feedback->force;
      }
    }
  });
  const SessionReport report = run_live(left_tube_patient(), options, input);
  done = true;
  device.join();

  EXPECT_EQ(report.end_reason, "duration");
  EXPECT_GT(input.left().counters().accepted, 50u);
  EXPECT_GT(input.left().feedback_sent(), 100u);
  // The tube pushed the held probe back towards its port, through the bridge.
  EXPECT_GT(pressing.packets, 50);
  EXPECT_GT(pressing.strongest.norm(), 1e-4) << "the soft tube gives way: ~0.7 mN";
  EXPECT_LT(pressing.strongest.dot(i.into), 0.0);
  EXPECT_LE(std::max(probing.strongest.norm(), pressing.strongest.norm()), 2.0 + 1e-12)
      << "within the device's force limit";
  EXPECT_GT(withdrawn.packets, 10);
  EXPECT_EQ(withdrawn.strongest, core::Vec3::Zero()) << "an empty port feels nothing";

  // The recorded states: the port empty before the first pose, the probe in at the poses,
  // the grasper's jaws closed, then the port empty again; the working port untouched.
  ASSERT_GT(report.inputs.size(), 10u);
  EXPECT_FALSE(report.inputs.front().second.second.inserted);
  const auto first_in = std::find_if(report.inputs.begin(), report.inputs.end(),
                                     [](const auto& step) { return step.second.second.inserted; });
  ASSERT_NE(first_in, report.inputs.end());
  const SecondPort& probe = first_in->second.second;
  EXPECT_EQ(probe.tool, LaparoscopicTool::None);
  EXPECT_NEAR((probe.tip - above).norm(), 0.0, 0.0025) << "at the device's first poses";
  EXPECT_NEAR((probe.axis - i.into).norm(), 0.0, 1e-9);
  const bool reached = std::any_of(report.inputs.begin(), report.inputs.end(), [&](const auto& s) {
    return s.second.second.inserted && s.second.second.tip == pressed;
  });
  EXPECT_TRUE(reached) << "the tip exactly at the pressed pose";
  const auto closed = std::find_if(report.inputs.begin(), report.inputs.end(),
                                   [](const auto& step) { return step.second.second.jaws_closed; });
  ASSERT_NE(closed, report.inputs.end()) << "the jaws bit closed the second tool's jaws";
  EXPECT_EQ(closed->second.second.tool, LaparoscopicTool::Grasper);
  EXPECT_TRUE(closed->second.second.inserted);
  EXPECT_FALSE(closed->second.jaws_closed) << "the working port's jaws stay open";
  EXPECT_FALSE(report.inputs.back().second.second.inserted) << "withdrawn";
  EXPECT_GT(closed - first_in, 0);
  for (const auto& [step, state] : report.inputs)
    EXPECT_EQ(state.tip, camera.tip);
  const auto count = [&](const std::string& kind) {
    return std::count_if(report.events.begin(), report.events.end(),
                         [&](const auto& e) { return e.kind == kind; });
  };
  EXPECT_GE(count("tool-inserted"), 1);
  EXPECT_GE(count("tool-withdrawn"), 1);

  // The recorded states replay the session bit for bit without the devices.
  const RecordedInput recorded(report.inputs);
  HeadlessRunOptions replay = options;
  replay.instrument = &recorded;
  const SessionReport again = run_headless(left_tube_patient(), replay);
  EXPECT_EQ(again.final_state_hash, report.final_state_hash);
}

TEST(TwoHandedInput, threaded_a_second_device_loop_answers_the_left_device_from_the_tube) {
  const Isthmus i = isthmus();
  InstrumentState camera;
  camera.tip = i.point - 0.05 * i.into;
  camera.axis = i.into;
  orthonormalise(camera);
  DeviceLimits limits;
  limits.min_force = 0.0;  // the tube's millinewton, rendered
  TwoHandedInput input(std::make_unique<StillLaparoscope>(camera), {"127.0.0.1", 0}, limits);
  HeadlessRunOptions options;
  options.duration = 0.6;
  options.instrument_body = "tube-left";
  options.end_when_complete = false;
  const LiveInstrument live(input);
  options.instrument = &live;
  SessionRunner runner(left_tube_patient(), options);
  input.start_realtime(runner);
  ASSERT_NE(input.left().loop(), nullptr) << "the left device has a loop of its own";

  // The probe in from 2 cm above the tube, 3 mm past its front after 0.2 s, then held there
  // (a tool put in inside the tube would never have crossed its surface).
  const core::Vec3 above = i.point - 0.02 * i.into, pressed = i.point + 0.003 * i.into;
  const Eigen::Quaterniond q = Eigen::Quaterniond::FromTwoVectors(core::Vec3::UnitZ(), i.into);
  std::atomic<bool> done{false};
  std::atomic<double> strongest{0.0};
  std::atomic<int> packets{0};
  std::thread device([&] {
    SimulatedDevice client(input.left_port());
    DevicePose pose;
    pose.orientation = {q.w(), q.x(), q.y(), q.z()};
    const auto start = std::chrono::steady_clock::now();
    for (std::uint32_t n = 1; !done.load(); ++n) {
      const double t =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      pose.position = t < 0.2 ? above + (t / 0.2) * (pressed - above) : pressed;
      pose.sequence = n;
      client.send(pose);
      for (auto feedback = client.receive(1); feedback; feedback = client.receive(0)) {
        ++packets;
        if (feedback->force.norm() > strongest.load()) strongest = feedback->force.norm();
      }
    }
  });
  // The physics thread's part, paced by the wall clock.
  const auto began = std::chrono::steady_clock::now();
  while (!runner.finished()) {
    std::this_thread::sleep_until(began +
                                  std::chrono::duration_cast<std::chrono::nanoseconds>(
                                      std::chrono::duration<double>(runner.world().time())));
    runner.step(input.next(runner.world().time_step()));
    input.after_step(runner);
  }
  input.stop_realtime();
  done = true;
  device.join();

  EXPECT_TRUE(runner.instrument_state().second.inserted);
  EXPECT_EQ(runner.instrument_state().second.tip, pressed);
  EXPECT_GT(packets.load(), 100) << "the loop answers at about 1 kHz";
  EXPECT_GT(strongest.load(), 1e-4) << "the local proxy on the tube pushes back";
  RealtimeStats stats;
  stats.wall_time = 0.6;
  input.add_stats(stats);
  EXPECT_FALSE(stats.device) << "the right hand here is no device";
  EXPECT_TRUE(stats.left_device);
  EXPECT_GT(stats.left_device_poses, 50);
  EXPECT_GE(stats.left_device_feedback, packets.load());
  EXPECT_NEAR(stats.left_feedback_rate, static_cast<double>(stats.left_device_feedback) / 0.6,
              1e-9);
}

TEST(TwoHandedInput, the_left_devices_abort_button_ends_the_session) {
  TwoHandedInput input(std::make_unique<StillLaparoscope>(InstrumentState{}), {"127.0.0.1", 0});
  SimulatedDevice client(input.left_port());
  DevicePose pose;
  pose.sequence = 1;
  pose.buttons = kDeviceAbortButton;
  ASSERT_TRUE(client.send(pose));
  InstrumentState state;
  for (int tries = 0; tries < 1000 && !state.abort; ++tries) {
    state = input.next(0.001);
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  EXPECT_TRUE(state.abort);
  EXPECT_TRUE(state.second.inserted);
  EXPECT_NE(input.describe().find("left hand: haptic device on udp 127.0.0.1:" +
                                  std::to_string(input.left_port())),
            std::string::npos)
      << input.describe();
}

}  // namespace
}  // namespace viscera::sim
