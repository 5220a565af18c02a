// viscera_device_emulator: a haptic device on loopback for trying a windowed session by hand
// (issue 16 item 3). Sends pose packets at --rate Hz to 127.0.0.1:--port for --seconds s and
// prints what came back as JSON: feedback packets, their rate and the gaps between them.
//   xvfb-run -a viscera-sim run h.vscene --input udp:5005 &
//   viscera_device_emulator --port 5005 --package h.vscene --seconds 10
// With --package the tool starts at the scenario's starting pose and moves 3 mm along its shaft
// and back once a second; without, it holds still at the origin.
// With --hand left it is the second instrument port's device (viscera-sim run … --left-device
// udp:PORT): it starts where the keyboard's left hand puts its tool in (second_port_entry).
// --buttons sets every pose's button bits (device_input.h: pedals, jaws, tool bits 4–6,
// bit 8 = the left tool out of its port).

#include <CLI/CLI.hpp>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "core/error.h"
#include "core/package/scenario_package.h"
#include "simulator/session/manual_control.h"
#include "tests/bench/device_emulator.h"

int main(int argc, char** argv) {
  CLI::App app{"Haptic device emulator over UDP loopback", "viscera_device_emulator"};
  int port = 0;
  double seconds = 10.0, rate = 1000.0, stroke = 0.003;
  std::string package;
  std::string hand = "right";
  std::uint32_t buttons = 0;
  app.add_option("--port", port, "UDP port viscera-sim listens on")
      ->required()
      ->check(CLI::Range(1, 65535));
  app.add_option("--seconds", seconds, "How long to send")->check(CLI::PositiveNumber);
  app.add_option("--rate", rate, "Poses per second")->check(CLI::Range(1.0, 20000.0));
  app.add_option("--package", package, "Start at this scenario's starting pose");
  app.add_option("--stroke", stroke, "m the tool moves along its shaft and back each second");
  app.add_option("--hand", hand, "right: the working port's device; left: the second port's")
      ->check(CLI::IsMember({"right", "left"}));
  app.add_option("--buttons", buttons, "Button bits of every pose (device_input.h)");
  CLI11_PARSE(app, argc, argv);
  try {
    viscera::sim::InstrumentState start;
    if (!package.empty()) {
      const viscera::core::Scenario scenario = viscera::core::read_package(package);
      start = viscera::sim::starting_pose(scenario, scenario.session.instrument.optics_angle);
    }
    if (hand == "left") {
      start.second = viscera::sim::second_port_entry(start);
      start = viscera::sim::in_port(start, 1);
    }
    const auto report = viscera::testing::emulate_device(
        static_cast<std::uint16_t>(port), seconds,
        [&](double t) {
          viscera::sim::InstrumentState pose = start;
          pose.tip += 0.5 * stroke * (1.0 - std::cos(2.0 * std::numbers::pi * t)) * start.axis;
          viscera::sim::DevicePose sent = viscera::testing::pose_of(pose);
          sent.buttons = buttons;
          return sent;
        },
        rate);
    const nlohmann::json out = {
        {"poses_sent", report.poses_sent},        {"feedback", report.feedback},
        {"feedback_per_s", report.feedback_rate}, {"gap_p50_ms", 1e3 * report.gap_p50},
        {"gap_p90_ms", 1e3 * report.gap_p90},     {"gap_p99_ms", 1e3 * report.gap_p99},
        {"gap_max_ms", 1e3 * report.gap_max},     {"max_force_n", report.max_force}};
    std::cout << out.dump(2) << "\n";
  } catch (const std::exception& e) {
    std::cerr << "viscera_device_emulator: " << e.what() << "\n";
    return static_cast<int>(viscera::core::exit_code_for(e));
  }
  return 0;
}
