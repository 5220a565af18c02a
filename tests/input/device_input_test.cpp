// A haptic device on real UDP sockets (loopback) driving a live session: the instrument
// follows the poses, forces come back, and the recorded inputs replay bit for bit.

#include "simulator/input/device_input.h"

#include <gtest/gtest.h>

#include <atomic>
#include <numbers>
#include <thread>

#include "simulator/haptics/simulated_device.h"
#include "simulator/input/live_session.h"
#include "simulator/session/headless_session.h"
#include "tests/support/tet_block.h"

namespace viscera::sim {
namespace {

/// A 4 × 4 × 2 cm soft block with its bottom held, top face at z = 2 cm.
core::Scenario soft_block() {
  core::Scenario scenario = viscera::testing::held_soft_block();
  scenario.session.gravity = core::Vec3::Zero();
  return scenario;
}

TEST(DeviceInput, pose_quaternion_turns_the_rest_frame_into_the_scene) {
  DevicePose pose;
  pose.position = {0.01, 0.02, 0.03};
  const double half = std::numbers::pi / 4.0;  // 90° about x: +z → −y, +y → +z
  pose.orientation = {std::cos(half), std::sin(half), 0.0, 0.0};
  pose.inflow_valve = 1.0F;
  pose.outflow_valve = 0.25F;
  const InstrumentState state = instrument_from_pose(pose);
  EXPECT_EQ(state.tip, pose.position);
  EXPECT_NEAR((state.axis - core::Vec3(0, -1, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((state.up - core::Vec3(0, 0, 1)).norm(), 0.0, 1e-12);
  EXPECT_EQ(state.inflow, 1.0);
  EXPECT_EQ(state.outflow, 0.25);
  EXPECT_FALSE(state.abort);
  pose.buttons = kDeviceAbortButton;
  pose.orientation = {0, 0, 0, 0};  // no orientation: the rest frame
  const InstrumentState aborting = instrument_from_pose(pose);
  EXPECT_TRUE(aborting.abort);
  EXPECT_FALSE(aborting.electrode);
  EXPECT_EQ(aborting.axis, core::Vec3::UnitZ());
  pose.buttons = kDeviceCuttingPedal;
  EXPECT_TRUE(instrument_from_pose(pose).electrode);
  EXPECT_FALSE(instrument_from_pose(pose).coagulation);
  pose.buttons = kDeviceCoagulationPedal;
  EXPECT_TRUE(instrument_from_pose(pose).coagulation);
  EXPECT_FALSE(instrument_from_pose(pose).electrode);
  // The suction–irrigation cannula (tool 5): jaws bit = suction valve, bit 7 = irrigation valve.
  pose.buttons = kDeviceIrrigating | (5U << kDeviceToolShift);
  EXPECT_TRUE(instrument_from_pose(pose).irrigating);
  EXPECT_FALSE(instrument_from_pose(pose).jaws_closed);
  EXPECT_EQ(instrument_from_pose(pose).tool, LaparoscopicTool::Suction);
  pose.buttons = kDeviceJawsClosed | (5U << kDeviceToolShift);
  EXPECT_FALSE(instrument_from_pose(pose).irrigating);
  EXPECT_TRUE(instrument_from_pose(pose).jaws_closed);
  EXPECT_EQ(kDeviceIrrigating & (kDeviceToolMask | kDeviceJawsClosed | kDeviceAbortButton |
                                 kDeviceCuttingPedal | kDeviceCoagulationPedal),
            0U);
}

TEST(DeviceInput, a_device_on_loopback_drives_a_live_session_and_feels_the_tissue) {
  const core::Scenario scenario = soft_block();
  InstrumentState start;
  start.tip = {0.02, 0.021, 0.04};  // 2 cm above the top face
  DeviceInput input({"127.0.0.1", 0}, start);
  HeadlessRunOptions options;
  options.duration = 0.6;
  options.record_inputs = true;
  options.instrument_stiffness = 200.0;

  std::atomic<bool> done{false};
  std::atomic<double> max_force{0.0};
  std::atomic<int> feedback_packets{0};
  std::thread device([&] {
    SimulatedDevice client(input.port());
    DevicePose pose;
    for (std::uint32_t i = 1; !done.load(); ++i) {
      pose.sequence = i;
      pose.position = {0.02, 0.021, std::max(0.014, 0.04 - 0.0002 * i)};  // 6 mm deep
      pose.inflow_valve = 1.0F;
      client.send(pose);
      // Wait up to 1 ms for feedback, then take whatever else has arrived.
      for (auto feedback = client.receive(1); feedback; feedback = client.receive(0)) {
        ++feedback_packets;
        if (feedback->force.norm() > max_force.load()) max_force = feedback->force.norm();
      }
    }
  });
  const SessionReport report = run_live(scenario, options, input);
  done = true;
  device.join();

  EXPECT_EQ(report.end_reason, "duration");
  EXPECT_GT(input.counters().accepted, 50u);
  EXPECT_GT(input.feedback_sent(), 100u);
  EXPECT_GT(feedback_packets.load(), 100);
  EXPECT_GT(max_force.load(), 0.1) << "the tissue pushed back through the bridge";
  EXPECT_LE(max_force.load(), 2.0 + 1e-12) << "within the device's force limit";
  // The instrument followed the device: the recorded states are the poses' (the last one sent
  // may arrive after the session ended, so compare with the deepest position reached).
  ASSERT_GT(report.inputs.size(), 10u);
  EXPECT_EQ(report.inputs.front().second.tip, start.tip);
  EXPECT_NEAR(report.inputs.back().second.tip.z(), 0.014, 1e-12);
  EXPECT_EQ(report.inputs.back().second.inflow, 1.0);

  // The recorded states replay the session bit for bit without the device.
  const RecordedInput recorded(report.inputs);
  HeadlessRunOptions replay = options;
  replay.instrument = &recorded;
  const SessionReport again = run_headless(scenario, replay);
  EXPECT_EQ(again.final_state_hash, report.final_state_hash);
  EXPECT_EQ(again.checkpoints, report.checkpoints);
}

}  // namespace
}  // namespace viscera::sim
