// `viscera-sim run --input/--device`: a haptic device over UDP drives a headless session
// through the real program (poses in, forces out, on loopback), the recorded trace drives the
// window and replays bit for bit, and a gamepad request without a pad falls back to the keyboard.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <atomic>
#include <thread>

#include "simulator/haptics/simulated_device.h"
#include "simulator/haptics/udp_socket.h"
#include "simulator/session/manual_control.h"
#include "simulator/session/session_trace.h"
#include "tests/support/command_runner.h"
#include "tests/support/free_port.h"
#include "tests/support/test_paths.h"
#include "tests/view/view_fixtures.h"

namespace viscera {
namespace {

using testing::run_program;
using testing::shell_quote;

using testing::free_port;

/// Runs `viscera-sim run PATIENT --device udp:PORT` with `mode` (" --headless" or a window's
/// size) for 1 s while a simulated device pushes the tool 2 mm along its shaft; checks the
/// force packets, the recorded states and the bit-identical replay.
void drive_with_device(const std::string& mode) {
  const auto& patient = testing::hysteroscopy_patient();
  const auto dir = testing::scratch_dir();
  const auto trace = dir / "device.json";
  const double angle = patient.scenario.session.instrument.optics_angle;
  const sim::InstrumentState start = sim::starting_pose(patient.scenario, angle);
  const std::uint16_t port = free_port();

  std::atomic<bool> done{false};
  std::atomic<int> forces{0};
  std::thread device([&] {
    sim::SimulatedDevice client(port);
    sim::DevicePose pose;
    for (std::uint32_t i = 1; !done.load(); ++i) {
      pose.sequence = i;
      // 2 mm along the shaft over the first 10 packets, then hold (a loaded machine may let
      // only tens of packets through in the session's second).
      pose.position = start.tip + 0.0002 * std::min<std::uint32_t>(i, 10) * start.axis;
      const Eigen::Quaterniond q =
          Eigen::Quaterniond::FromTwoVectors(core::Vec3::UnitZ(), start.axis);
      pose.orientation = {q.w(), q.x(), q.y(), q.z()};
      pose.outflow_valve = 0.5F;
      client.send(pose);
      for (auto feedback = client.receive(1); feedback; feedback = client.receive(0))
        ++forces;
    }
  });
  const auto result = run_program("viscera-sim",
                                  "run " + shell_quote(patient.package.string()) + mode +
                                      " --duration 1 --device udp:" + std::to_string(port) +
                                      " --record " + shell_quote(trace.string()),
                                  dir);
  done = true;
  device.join();
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.err.find("udp 127.0.0.1:" + std::to_string(port)), std::string::npos)
      << result.err;
  EXPECT_GT(forces.load(), 10) << "force packets came back";
  const sim::SessionTrace recorded = sim::read_trace(trace);
  ASSERT_GE(recorded.inputs.size(), 2u);  // the starting pose, then the device's
  const sim::InstrumentState& last = recorded.inputs.back().second;
  EXPECT_NEAR((last.tip - (start.tip + 0.002 * start.axis)).norm(), 0.0, 1e-12)
      << "the instrument followed the device";
  EXPECT_NEAR((last.axis - start.axis).norm(), 0.0, 1e-9);
  EXPECT_EQ(last.outflow, 0.5);
  const auto replay = run_program("viscera-sim", "replay " + shell_quote(trace.string()), dir);
  EXPECT_EQ(replay.exit_code, 0) << replay.err;
  EXPECT_NE(replay.out.find("replay identical"), std::string::npos) << replay.out;
}

TEST(SimCliInput, a_device_over_udp_drives_a_headless_run_and_gets_force_packets) {
  drive_with_device(" --headless");
}

TEST(SimCliInput, a_device_over_udp_drives_the_window) {
  drive_with_device(" --width 320 --height 240");
}

TEST(SimCliInput, a_recorded_trace_is_an_input_and_stays_identical) {
  const auto& patient = testing::hysteroscopy_patient();
  const auto dir = testing::scratch_dir();
  const auto first = dir / "first.json";
  const auto second = dir / "second.json";
  // A keyboard session in the window (no keys pressed: the resting pose), recorded …
  auto result = run_program("viscera-sim",
                            "run " + shell_quote(patient.package.string()) +
                                " --input gamepad --duration 0.3 --width 320 --height 240 "
                                "--record " +
                                shell_quote(first.string()),
                            dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.err.find("no gamepad found"), std::string::npos) << result.err;
  // … drives a second run, in the window, whose own trace replays bit for bit.
  result = run_program("viscera-sim",
                       "run " + shell_quote(patient.package.string()) +
                           " --input trace:" + shell_quote(first.string()) +
                           " --width 320 --height 240 --record " + shell_quote(second.string()),
                       dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const sim::SessionTrace a = sim::read_trace(first), b = sim::read_trace(second);
  EXPECT_EQ(a.final_state_hash, b.final_state_hash);
  EXPECT_EQ(a.checkpoints, b.checkpoints);
  result = run_program("viscera-sim", "replay " + shell_quote(second.string()), dir);
  EXPECT_EQ(result.exit_code, 0) << result.err;
}

TEST(SimCliInput, refuses_inputs_that_cannot_work_with_exit_2) {
  const auto& patient = testing::hysteroscopy_patient();
  const auto dir = testing::scratch_dir();
  const std::string package = shell_quote(patient.package.string());
  for (const std::string args : {" --headless --input keyboard", " --input joystick",
                                 " --device trace:x.json", " --input udp:99999"}) {
    const auto result = run_program("viscera-sim", "run " + package + args, dir);
    EXPECT_EQ(result.exit_code, 2) << args << ": " << result.err;
  }
}

}  // namespace
}  // namespace viscera
