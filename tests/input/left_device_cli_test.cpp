// `viscera-sim run … --left-device udp:PORT` through the real program: two devices on loopback
// drive a headless laparoscopy session (the working port and the second port), the status line
// names both bound ports, and combinations that cannot work end with one sentence and exit 2.

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "core/package/scenario_package.h"
#include "simulator/haptics/simulated_device.h"
#include "simulator/haptics/udp_socket.h"
#include "simulator/input/device_input.h"
#include "simulator/session/session_trace.h"
#include "tests/simulator/left_tube_patient.h"
#include "tests/support/command_runner.h"
#include "tests/support/free_port.h"
#include "tests/support/test_paths.h"

namespace viscera {
namespace {

using testing::run_program;
using testing::shell_quote;

using testing::free_port;

/// The left tube patient written once as a package.
const std::filesystem::path& tube_package() {
  static const std::filesystem::path path = [] {
    const auto p = testing::scratch_dir() / "left-tube.vscene";
    core::write_package(testing::left_tube_patient(), p);
    return p;
  }();
  return path;
}

/// Sends `pose` (its sequence counted up) to 127.0.0.1:`port` until `done`; counts feedback.
void hold_device(std::uint16_t port, sim::DevicePose pose, const std::atomic<bool>& done,
                 std::atomic<int>& feedback) {
  sim::SimulatedDevice client(port);
  for (std::uint32_t n = 1; !done.load(); ++n) {
    pose.sequence = n;
    client.send(pose);
    for (auto packet = client.receive(1); packet; packet = client.receive(0))
      ++feedback;
  }
}

TEST(LeftDeviceCli, two_devices_drive_both_ports_of_a_headless_laparoscopy_session) {
  const auto dir = testing::scratch_dir();
  const auto trace = dir / "two-handed.json";
  const std::uint16_t right_port = free_port(), left_port = free_port();
  ASSERT_NE(right_port, left_port);
  sim::DevicePose right, left;
  right.position = {0.0, -0.15, 0.05};  // the laparoscope well clear of the tube
  left.position = {0.01, -0.12, 0.04};
  left.buttons = (1U << sim::kDeviceToolShift) | sim::kDeviceJawsClosed;  // a closed grasper
  std::atomic<bool> done{false};
  std::atomic<int> right_feedback{0}, left_feedback{0};
  std::thread right_device(hold_device, right_port, right, std::cref(done),
                           std::ref(right_feedback));
  std::thread left_device(hold_device, left_port, left, std::cref(done), std::ref(left_feedback));
  const auto result =
      run_program("viscera-sim",
                  "run " + shell_quote(tube_package().string()) +
                      " --headless --duration 0.5 --input udp:" + std::to_string(right_port) +
                      " --left-device udp:" + std::to_string(left_port) + " --record " +
                      shell_quote(trace.string()),
                  dir);
  done = true;
  right_device.join();
  left_device.join();
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.err.find("udp 127.0.0.1:" + std::to_string(right_port)), std::string::npos)
      << result.err;
  EXPECT_NE(result.err.find("left hand's haptic device drives the second port: send pose "
                            "packets to udp 127.0.0.1:" +
                            std::to_string(left_port)),
            std::string::npos)
      << result.err;
  EXPECT_GT(right_feedback.load(), 10);
  EXPECT_GT(left_feedback.load(), 10) << "the second port's forces came back to the left device";
  const sim::SessionTrace recorded = sim::read_trace(trace);
  ASSERT_GE(recorded.inputs.size(), 2u);
  const sim::InstrumentState& last = recorded.inputs.back().second;
  EXPECT_EQ(last.tip, right.position);
  ASSERT_TRUE(last.second.inserted);
  EXPECT_EQ(last.second.tip, left.position);
  EXPECT_EQ(last.second.tool, sim::LaparoscopicTool::Grasper);
  EXPECT_TRUE(last.second.jaws_closed);
  const auto replay = run_program("viscera-sim", "replay " + shell_quote(trace.string()), dir);
  EXPECT_EQ(replay.exit_code, 0) << replay.err;
}

TEST(LeftDeviceCli, refuses_combinations_that_cannot_work_with_one_sentence_and_exit_2) {
  const auto dir = testing::scratch_dir();
  const std::string package = shell_quote(tube_package().string());
  const std::pair<std::string, std::string> cases[] = {
      {" --headless --input udp:5123 --left-device udp:5123", "both name udp port 5123"},
      {" --headless --device udp:5123 --left-device udp:5123", "both name udp port 5123"},
      {" --headless --input udp:0 --left-device tcp:5", "is not udp:PORT"},
      {" --headless --input udp:0 --left-device udp:70000", "a port from 0 to 65535"},
      {" --headless --left-device udp:0", "needs a device on the working port"},
      {" --headless --input trace:x.json --left-device udp:0", "cannot join a script or a trace"},
  };
  for (const auto& [args, sentence] : cases) {
    const auto result = run_program("viscera-sim", "run " + package + args, dir);
    EXPECT_EQ(result.exit_code, 2) << args << ": " << result.err;
    EXPECT_NE(result.err.find("--left-device"), std::string::npos) << args << ": " << result.err;
    EXPECT_NE(result.err.find(sentence), std::string::npos) << args << ": " << result.err;
  }
}

}  // namespace
}  // namespace viscera
