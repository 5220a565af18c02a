// The threaded window session (issue 16 item 3): `viscera-sim run` in the window with a device
// emulator sending poses at 1 kHz over loopback. The physics runs on its own thread, the device
// I/O on another, the view draws snapshots; the report says how it kept time, and the recorded
// trace replays headless (`viscera-sim replay`, one thread) to the same final state hash.

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <thread>

#include "simulator/haptics/udp_socket.h"
#include "simulator/session/manual_control.h"
#include "simulator/session/session_trace.h"
#include "tests/bench/device_emulator.h"
#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"
#include "tests/view/view_fixtures.h"

namespace viscera {
namespace {

using testing::run_program;
using testing::shell_quote;

TEST(ThreadedWindow, a_device_session_in_the_window_replays_headless_to_the_same_hash) {
  const auto& patient = testing::hysteroscopy_patient();
  const auto dir = testing::scratch_dir();
  const auto trace = dir / "window.json";
  const auto report_dir = dir / "report";
  const double angle = patient.scenario.session.instrument.optics_angle;
  const sim::InstrumentState start = sim::starting_pose(patient.scenario, angle);
  std::uint16_t port = 0;
  {
    const sim::UdpSocket probe("127.0.0.1", 0);
    port = probe.local().port;
  }
  // The emulator moves the tool 3 mm along the shaft and back, once a second, from 1 kHz poses.
  std::atomic<bool> stop{false};
  testing::EmulatorReport measured;
  std::thread device([&] {
    measured = testing::emulate_device(
        port, 20.0,
        [&](double t) {
          sim::InstrumentState state = start;
          state.tip += 0.0015 * (1.0 - std::cos(2.0 * std::numbers::pi * t)) * start.axis;
          return testing::pose_of(state);
        },
        1000.0, &stop);
  });
  const auto result = run_program(
      "viscera-sim",
      "run " + shell_quote(patient.package.string()) + " --width 320 --height 240 --duration 1.5" +
          " --input udp:" + std::to_string(port) + " --record " + shell_quote(trace.string()) +
          " --report " + shell_quote(report_dir.string()),
      dir);
  stop = true;
  device.join();
  ASSERT_EQ(result.exit_code, 0) << result.err;

  // The device was answered from the device thread while the session ran.
  EXPECT_GT(measured.poses_sent, 100);
  EXPECT_GT(measured.feedback, 100) << "feedback packets reached the device";
  std::ifstream in(report_dir / "report.json");
  const nlohmann::json report = nlohmann::json::parse(in);
  ASSERT_TRUE(report["realtime"].is_object()) << "a window session reports how it kept time";
  const nlohmann::json& realtime = report["realtime"];
  EXPECT_GT(realtime["frames"].get<long long>(), 0);
  EXPECT_EQ(realtime["physics_steps"].get<long long>(), report["steps"].get<long long>());
  ASSERT_TRUE(realtime["device"].is_object());
  EXPECT_GT(realtime["device"]["feedback"].get<long long>(), 100);
  EXPECT_GT(realtime["device"]["poses"].get<long long>(), 100);

  // The trace of the threaded session replays on one thread, bit for bit.
  const sim::SessionTrace recorded = sim::read_trace(trace);
  ASSERT_GE(recorded.inputs.size(), 10u) << "the device's poses were recorded";
  EXPECT_EQ(recorded.final_state_hash, report["final_state_hash"].get<std::string>());
  const auto replay =
      run_program("viscera-sim", "replay " + shell_quote(trace.string()) + " --json", dir);
  ASSERT_EQ(replay.exit_code, 0) << replay.err;
  const nlohmann::json replayed = nlohmann::json::parse(replay.out);
  EXPECT_EQ(replayed["final_state_hash"], report["final_state_hash"]);
  EXPECT_TRUE(replayed["realtime"].is_null()) << "a replay is headless";
}

}  // namespace
}  // namespace viscera
