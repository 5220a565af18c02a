// Haptic feedback of a windowed session (issue 16 item 3 target: feedback ≥ 990 packets/s, gap
// between feedback packets p99 ≤ 2 ms, view ≥ 30 fps): `viscera-sim run h.vscene --input
// udp:PORT` in its window on the hysteroscopy template while the device emulator
// (device_emulator.h) sends poses at 1 kHz over loopback, moving the tool 3 mm along its shaft
// and back once a second. The emulator measures what the device receives; the session's
// report.json gives the view's frame rate. One iteration of VISCERA_WINDOW_BENCH_SECONDS (10)
// simulated seconds. Needs an X server: xvfb-run -a build/bin/viscera_window_feedback_bench.

#include <benchmark/benchmark.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <thread>

#include "core/package/scenario_package.h"
#include "simulator/haptics/udp_socket.h"
#include "simulator/session/manual_control.h"
#include "tests/bench/device_emulator.h"

namespace {

namespace fs = std::filesystem;

/// `viscera new --template hysteroscopy` once, in the build tree.
const fs::path& package() {
  static const fs::path made = [] {
    const fs::path dir = fs::path(VISCERA_BINARY_DIR) / "bench" / "window-feedback";
    const fs::path h = dir / "h.vscene";
    if (!fs::exists(h / "manifest.json")) {
      fs::create_directories(dir);
      const std::string bin = std::string(VISCERA_BINARY_DIR) + "/bin/viscera";
      if (std::system(
              (bin + " new --template hysteroscopy -o '" + h.string() + "' > /dev/null").c_str()) !=
          0)
        std::abort();
    }
    return h;
  }();
  return made;
}

double seconds() {
  const char* text = std::getenv("VISCERA_WINDOW_BENCH_SECONDS");
  return text != nullptr ? std::atof(text) : 10.0;
}

void BM_WindowedDeviceFeedback(benchmark::State& state) {
  const fs::path& h = package();
  const viscera::core::Scenario scenario = viscera::core::read_package(h);
  const double angle = scenario.session.instrument.optics_angle;
  const viscera::sim::InstrumentState start = viscera::sim::starting_pose(scenario, angle);
  const fs::path report_dir = h.parent_path() / "report";
  for (auto _ : state) {
    std::uint16_t port = 0;
    {
      const viscera::sim::UdpSocket probe("127.0.0.1", 0);
      port = probe.local().port;
    }
    fs::remove_all(report_dir);
    std::atomic<bool> ended{false};
    int exit_code = -1;
    std::thread session([&] {
      const std::string command = std::string(VISCERA_BINARY_DIR) + "/bin/viscera-sim run '" +
                                  h.string() + "' --input udp:" + std::to_string(port) +
                                  " --duration " + std::to_string(seconds()) + " --report '" +
                                  report_dir.string() + "' > /dev/null 2>&1";
      exit_code = std::system(command.c_str());
      ended = true;
    });
    const viscera::testing::EmulatorReport device = viscera::testing::emulate_device(
        port, 10.0 * seconds() + 60.0,
        [&](double t) {
          viscera::sim::InstrumentState pose = start;
          pose.tip += 0.0015 * (1.0 - std::cos(2.0 * std::numbers::pi * t)) * start.axis;
          return viscera::testing::pose_of(pose);
        },
        1000.0, &ended);
    session.join();
    if (exit_code != 0) {
      state.SkipWithError("viscera-sim failed");
      return;
    }
    std::ifstream in(report_dir / "report.json");
    const nlohmann::json report = nlohmann::json::parse(in);
    const nlohmann::json& realtime = report.at("realtime");
    state.counters["feedback_per_s"] = device.feedback_rate;
    state.counters["gap_p50_ms"] = 1e3 * device.gap_p50;
    state.counters["gap_p99_ms"] = 1e3 * device.gap_p99;
    state.counters["gap_max_ms"] = 1e3 * device.gap_max;
    state.counters["view_fps"] = realtime.at("view_fps").get<double>();
    state.counters["late_steps"] = realtime.at("late_steps").get<double>();
    state.counters["max_lag_ms"] = 1e3 * realtime.at("max_lag").get<double>();
    state.counters["real_time_factor"] = report.at("real_time_factor").get<double>();
  }
}
BENCHMARK(BM_WindowedDeviceFeedback)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
