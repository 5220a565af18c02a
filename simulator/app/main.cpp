/// `viscera-sim`: the simulator runtime. Opens a scenario package and runs a session on it, or
/// replays a recorded session and checks it bit for bit.
/// Exit codes (DESIGN.md §9): 0 success, 1 internal error, 2 usage, 3 unreadable or invalid
/// input, 4 validation failed (a replay that departs from its recording), 5 the simulation
/// failed (core::SimulationError: the body, node, step and likely cause in one sentence).

#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include "core/cli/command_line.h"
#include "core/error.h"
#include "core/json_text.h"
#include "core/package/scenario_package.h"
#include "simulator/app/fluid_command.h"
#include "simulator/app/live_inputs.h"
#include "simulator/app/session_output.h"
#include "simulator/input/input_spec.h"
#include "simulator/input/live_session.h"
#include "simulator/report/html_report.h"
#include "simulator/session/headless_session.h"
#include "simulator/session/manual_control.h"
#include "simulator/session/session_trace.h"
#include "simulator/view/view_session.h"

namespace {

namespace fs = std::filesystem;
using viscera::app::publish;
using viscera::app::write_html;
using viscera::core::read_json_file;
using viscera::sim::SessionReport;

struct RunOptions {
  std::string package;
  bool headless = false;
  double duration = 0.0;
  std::string report_dir;
  std::string script;
  std::string record;
  bool json = false;
  std::string snapshot;         ///< PNG of the endoscopic view (offscreen)
  double snapshot_time = -1.0;  ///< s; negative: after the run
  int width = 1280, height = 720;
  bool plain_optics = false;   ///< no distortion, depth of field or field stop
  double optics = -1.0;        ///< ° of the angled optics; negative: the script's or scenario's
  bool html = false;           ///< also write report.html with its plots (needs X)
  std::string reference;       ///< an expert's report.json to compare against
  std::string input;           ///< keyboard | gamepad | udp:PORT | trace:FILE | script:FILE
  std::string device;          ///< udp:PORT (the same as --input udp:PORT)
  std::string left_device;     ///< udp:PORT: a haptic device on the second instrument port
  double render_scale = -1.0;  ///< lens pass scene resolution; negative: 0.5 in a window, else 1
};

/// The trace that replays `report`'s session.
viscera::sim::SessionTrace make_trace(const RunOptions& options,
                                      const viscera::sim::HeadlessRunOptions& run,
                                      const nlohmann::json& script, double optics_angle,
                                      const SessionReport& report) {
  viscera::sim::SessionTrace trace;
  trace.package = run.package;
  trace.manifest_sha256 = viscera::sim::package_manifest_sha256(options.package);
  trace.duration = run.duration;
  trace.body = run.instrument_body;
  trace.stiffness = run.instrument_stiffness;
  trace.perforation_depth = run.perforation_depth;
  trace.force_warning = run.force_warning;
  trace.checkpoint_interval = run.checkpoint_interval;
  trace.script = script;
  trace.optics_angle = optics_angle;
  if (script.is_null()) trace.inputs = report.inputs;
  trace.checkpoints = report.checkpoints;
  trace.final_state_hash = report.final_state_hash;
  trace.end_reason = report.end_reason;
  return trace;
}

/// The view of a session, offscreen for snapshots and videos.
std::unique_ptr<viscera::view::EndoscopicView> make_view(const viscera::core::Scenario& scenario,
                                                         const std::string& package,
                                                         const RunOptions& options, bool offscreen,
                                                         const std::string& bindings = "") {
  viscera::view::ViewOptions view;
  view.width = options.width;
  view.height = options.height;
  view.offscreen = offscreen;
  view.lens_effects = !options.plain_optics;
  // A live window needs its frame rate; snapshots and videos take their time for full detail.
  view.render_scale = options.render_scale > 0.0 ? options.render_scale : (offscreen ? 1.0 : 0.5);
  // Without --render-scale the window trades resolution for its frame rate (≥ 30 fps).
  view.adaptive_resolution = !offscreen && options.render_scale <= 0.0;
  if (!offscreen) view.bindings = bindings;
  return std::make_unique<viscera::view::EndoscopicView>(scenario, package, view);
}

/// The input source of a run: --device, else --input, else --script, else the keyboard.
viscera::sim::InputSpec input_spec(RunOptions& options) {
  using viscera::sim::InputKind;
  viscera::sim::InputSpec spec;
  if (!options.device.empty()) {
    spec = viscera::sim::parse_input_spec(options.device);
    if (spec.kind != InputKind::Udp)
      throw viscera::core::UsageError("--device takes udp:PORT (see --input for other sources)");
  } else if (!options.input.empty()) {
    spec = viscera::sim::parse_input_spec(options.input);
  }
  if (spec.kind == InputKind::Script) options.script = spec.file;
  if (!options.script.empty() && spec.kind != InputKind::Script &&
      (!options.input.empty() || !options.device.empty()))
    throw viscera::core::UsageError("--script and --input/--device name two inputs; give one");
  if (!options.script.empty()) spec = {InputKind::Script, 0, options.script};
  return spec;
}

/// The second port's device of a run (--left-device udp:PORT), or nullopt. It drives the left
/// hand beside a live input of the working port: a device (--input/--device udp:PORT), or the
/// keyboard or a gamepad in a window; anything else is a core::UsageError.
std::optional<viscera::sim::InputSpec> left_device_spec(const RunOptions& options,
                                                        const viscera::sim::InputSpec& right) {
  using viscera::sim::InputKind;
  if (options.left_device.empty()) return std::nullopt;
  const auto fail = [](const std::string& why) -> std::optional<viscera::sim::InputSpec> {
    throw viscera::core::UsageError(
        "--left-device " + why +
        " (accepted: --left-device udp:PORT with --input/--device udp:PORT, or in a window with "
        "the keyboard or a gamepad)");
  };
  viscera::sim::InputSpec left;
  try {
    left = viscera::sim::parse_input_spec(options.left_device);
  } catch (const viscera::core::UsageError&) {
    return fail("\"" + options.left_device + "\" is not udp:PORT with a port from 0 to 65535");
  }
  if (left.kind != InputKind::Udp) return fail("\"" + options.left_device + "\" is not udp:PORT");
  if (right.kind == InputKind::Script || right.kind == InputKind::Trace)
    return fail("cannot join a script or a trace, which drives both ports itself");
  if (options.headless && right.kind != InputKind::Udp)
    return fail("in a --headless run needs a device on the working port as well");
  if (!options.snapshot.empty()) return fail("cannot join --snapshot, which runs at full speed");
  if (right.kind == InputKind::Udp && right.port != 0 && right.port == left.port)
    return fail("and the working port's device both name udp port " + std::to_string(left.port) +
                "; give each device its own port (or 0 for any free one)");
  return left;
}

int run(RunOptions options) {
  using viscera::sim::InputKind;
  if (options.headless && !options.snapshot.empty()) {
    throw viscera::core::UsageError(
        "--snapshot renders the endoscopic view, which a --headless session never opens");
  }
  const viscera::sim::InputSpec spec = input_spec(options);
  const std::optional<viscera::sim::InputSpec> left = left_device_spec(options, spec);
  const bool live = spec.kind == InputKind::Keyboard || spec.kind == InputKind::Gamepad ||
                    spec.kind == InputKind::Udp;
  if (live && spec.kind != InputKind::Keyboard && !options.snapshot.empty())
    throw viscera::core::UsageError("--snapshot runs at full speed; a live input cannot");
  viscera::core::Scenario scenario = viscera::core::read_package(options.package);
  if (left && scenario.session.instrument.kind != "laparoscope")
    throw viscera::core::UsageError(
        "--left-device drives the second instrument port, which only a "
        "laparoscopy session (a \"laparoscope\" instrument) has");
  // A recorded trace replayed as the input brings its own instrument settings.
  std::optional<viscera::sim::SessionTrace> recorded;
  if (spec.kind == InputKind::Trace) recorded = viscera::sim::read_trace(spec.file);
  // The optics: --optics, else the trace's or script's, else the scenario's instrument.
  if (options.optics >= 0.0) {
    scenario.session.instrument.optics_angle = options.optics;
  } else if (recorded) {
    scenario.session.instrument.optics_angle = recorded->optics_angle;
  } else if (!options.script.empty()) {
    const nlohmann::json stated = read_json_file(options.script);
    if (stated.is_object() && stated.contains("optics_angle") && stated["optics_angle"].is_number())
      scenario.session.instrument.optics_angle = stated["optics_angle"].get<double>();
  }
  viscera::sim::HeadlessRunOptions run;
  run.package = fs::absolute(options.package).string();
  run.duration = options.duration > 0.0 ? options.duration : scenario.session.duration_limit;
  std::optional<viscera::sim::ScriptedTrajectory> script;
  std::unique_ptr<viscera::sim::InstrumentInput> replayed;
  nlohmann::json script_json;
  const double optics_angle = scenario.session.instrument.optics_angle;
  if (!options.script.empty()) {
    // Landmark places resolved on this patient; the trace keeps the resolved script.
    script_json = viscera::sim::resolve_script_landmarks(read_json_file(options.script),
                                                         scenario.landmarks, options.script);
    script = viscera::sim::ScriptedTrajectory::from_json(script_json, options.script, optics_angle);
    run.instrument = &*script;
    run.instrument_body = script->body();
    run.instrument_stiffness = script->stiffness();
    run.perforation_depth = script->perforation_depth();
    run.force_warning = script->force_warning();
    if (options.duration <= 0.0) run.duration = script->duration();
  } else if (recorded && (!recorded->body.empty() || !recorded->script.is_null() ||
                          !recorded->inputs.empty())) {
    replayed = recorded->input();
    script_json = recorded->script;
    run.instrument = replayed.get();
    run.instrument_body = recorded->body;
    run.instrument_stiffness = recorded->stiffness;
    run.perforation_depth = recorded->perforation_depth;
    run.force_warning = recorded->force_warning;
  }
  if (recorded && options.duration <= 0.0) run.duration = recorded->duration;
  run.record_inputs = !options.record.empty() || !options.report_dir.empty() || !options.headless;
  SessionReport report;
  const viscera::sim::InstrumentState start = viscera::sim::starting_pose(scenario, optics_angle);
  if (options.headless && spec.kind == InputKind::Udp) {
    viscera::app::LiveInputs inputs = viscera::app::open_live_input(spec, start, true);
    if (left) viscera::app::add_left_device(inputs, *left);
    std::cerr << inputs.status << "\n";
    report = viscera::sim::run_live(scenario, run, *inputs.live);
  } else if (options.headless) {
    // Without --input a headless run has no instrument (the body settles under gravity);
    // --input keyboard or gamepad asks for a window.
    if (run.instrument == nullptr && !options.input.empty())
      viscera::app::open_live_input(spec, start, true);  // throws UsageError
    report = viscera::sim::run_headless(scenario, run);
  } else if (!options.snapshot.empty()) {
    // Without a script the instrument rests at the starting pose, where the trainee would
    // begin.
    std::optional<viscera::sim::RecordedInput> resting;
    if (run.instrument == nullptr) {
      resting.emplace(std::vector<std::pair<long long, viscera::sim::InstrumentState>>{{0, start}});
      run.instrument = &*resting;
    }
    auto view = make_view(scenario, run.package, options, true);
    report = viscera::view::run_with_snapshot(scenario, run, *view, options.snapshot,
                                              options.snapshot_time);
  } else if (live) {
    // The trainee drives the instrument (keyboard and mouse, a gamepad or a haptic device),
    // starting where the scenario's first landmark can be seen.
    viscera::app::LiveInputs inputs = viscera::app::open_live_input(spec, start, false);
    if (left) viscera::app::add_left_device(inputs, *left);
    std::cerr << inputs.status << "\n";
    auto view = make_view(scenario, run.package, options, false, inputs.bindings);
    report =
        viscera::view::run_in_window(scenario, run, *view, inputs.manual.get(), inputs.live.get());
  } else {
    auto view = make_view(scenario, run.package, options, false,
                          "Esc or X: abort (the " + std::string(script ? "script" : "trace") +
                              " drives the instrument)");
    report = viscera::view::run_in_window(scenario, run, *view, nullptr);
  }
  const viscera::sim::SessionTrace trace =
      make_trace(options, run, script_json, optics_angle, report);
  if (!options.record.empty()) viscera::sim::write_trace(trace, options.record);
  if (!options.report_dir.empty())
    viscera::sim::write_trace(trace, fs::path(options.report_dir) / "trace.json");
  publish(report, options.report_dir, options.json, options.html, options.reference);
  if (!options.snapshot.empty() && !options.json)
    std::cout << "snapshot " << fs::absolute(options.snapshot).string() << "\n";
  return 0;
}

/// Runs the recorded session again and compares every checkpoint hash.
int replay(const std::string& trace_path, const std::string& report_dir, bool as_json,
           const std::string& video, int fps, const RunOptions& view_options) {
  const viscera::sim::SessionTrace trace = viscera::sim::read_trace(trace_path);
  if (viscera::sim::package_manifest_sha256(trace.package) != trace.manifest_sha256) {
    throw viscera::core::ValidationError("the package changed since the session was recorded",
                                         {trace.package, "", ""});
  }
  viscera::core::Scenario scenario = viscera::core::read_package(trace.package);
  scenario.session.instrument.optics_angle = trace.optics_angle;
  const std::unique_ptr<viscera::sim::InstrumentInput> input = trace.input();
  viscera::sim::HeadlessRunOptions run;
  run.package = trace.package;
  run.duration = trace.duration;
  run.checkpoint_interval = trace.checkpoint_interval;
  run.perforation_depth = trace.perforation_depth;
  run.force_warning = trace.force_warning;
  if (!trace.body.empty() || !trace.script.is_null() || !trace.inputs.empty()) {
    run.instrument = input.get();
    run.instrument_body = trace.body;
    run.instrument_stiffness = trace.stiffness;
  }
  SessionReport report;
  long long frames = 0;
  if (video.empty()) {
    report = viscera::sim::run_headless(scenario, run);
  } else {
    auto view = make_view(scenario, run.package, view_options, true);
    report = viscera::view::run_to_video(scenario, run, *view, video, fps, frames);
  }
  for (std::size_t i = 0; i < trace.checkpoints.size(); ++i) {
    if (i >= report.checkpoints.size() || report.checkpoints[i] != trace.checkpoints[i]) {
      throw viscera::core::ValidationError(
          "replay departs from the recording at step " + std::to_string(trace.checkpoints[i].first),
          {trace_path, "", ""});
    }
  }
  if (report.final_state_hash != trace.final_state_hash) {
    throw viscera::core::ValidationError("replay ends in a different state", {trace_path, "", ""});
  }
  publish(report, report_dir, as_json);
  if (!as_json) {
    std::cout << "replay identical: " << trace.checkpoints.size() << " checkpoints match\n";
    if (!video.empty())
      std::cout << "video " << fs::absolute(video).string() << " (" << frames << " frames at "
                << fps << " fps)\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Viscera simulator runtime", "viscera-sim"};
  app.require_subcommand(1);
  viscera::cli::add_common_options(app);

  RunOptions options;
  int exit_code = 0;
  auto* run_command = app.add_subcommand("run", "Run a session on a scenario package");
  run_command->add_option("package", options.package, "Package (.vscene folder or .vscz)")
      ->required();
  run_command->add_flag("--headless", options.headless,
                        "Run without a window (default: the endoscopic view, driven by the "
                        "script or by the keyboard and mouse)");
  run_command
      ->add_option("--duration", options.duration,
                   "Simulated seconds (default: the script's length or the scenario's limit)")
      ->check(CLI::NonNegativeNumber);
  run_command->add_option("--script", options.script,
                          "Scripted instrument trajectory (viscera-script JSON)");
  run_command->add_option(
      "--input", options.input,
      "What drives the instrument: keyboard (default), gamepad (SDL2 pad plus the keyboard), "
      "udp:PORT (a haptic device sending pose packets to 127.0.0.1:PORT; 0 picks a port), "
      "trace:FILE (a recorded session) or script:FILE");
  run_command->add_option("--device", options.device,
                          "udp:PORT: a haptic device drives the instrument (as --input udp:PORT)");
  run_command->add_option(
      "--left-device", options.left_device,
      "udp:PORT: a haptic device drives the laparoscopy session's second instrument port (the "
      "left hand) beside --input/--device udp:PORT or, in a window, the keyboard or a gamepad");
  run_command->add_option("--record", options.record, "Write the session's trace here for replay");
  run_command->add_option("--report", options.report_dir, "Folder for report.json");
  run_command->add_flag("--json", options.json, "Print the report as JSON");
  run_command->add_option(
      "--snapshot", options.snapshot,
      "Render the endoscopic view offscreen into this PNG (needs X, e.g. Xvfb)");
  run_command->add_option("--snapshot-time", options.snapshot_time,
                          "Simulated second of the snapshot (default: after the run)");
  run_command->add_option("--width", options.width, "View width in pixels")
      ->check(CLI::Range(64, 7680));
  run_command->add_option("--height", options.height, "View height in pixels")
      ->check(CLI::Range(64, 4320));
  run_command
      ->add_flag("--html", options.html,
                 "With --report: also write report.html and its plots (needs X, e.g. Xvfb)")
      ->needs(run_command->get_option("--report"));
  run_command
      ->add_option("--reference", options.reference,
                   "An expert's report.json the HTML report compares against")
      ->needs(run_command->get_option("--html"));
  run_command
      ->add_option("--optics", options.optics,
                   "Angle of the optics in degrees (0, 12, 30; default: the script's, else the "
                   "scenario's)")
      ->check(CLI::Range(0.0, 90.0));
  run_command->add_flag("--plain-optics", options.plain_optics,
                        "No barrel distortion, depth of field or round field stop");
  run_command
      ->add_option(
          "--render-scale", options.render_scale,
          "Resolution of the scene under the lens pass as a fraction of the view; fixes it "
          "(default: 0.5 in the window, lowered to 0.25 while it draws under 30 fps; 1 for "
          "snapshots)")
      ->check(CLI::Range(0.25, 1.0));
  run_command->callback([&] { exit_code = run(options); });

  std::string trace;
  std::string replay_report;
  bool replay_json = false;
  bool replay_headless = false;
  auto* replay_command =
      app.add_subcommand("replay", "Replay a recorded session and check it is bit-identical");
  replay_command->add_option("trace", trace, "Trace written by run --record")->required();
  replay_command->add_flag("--headless", replay_headless,
                           "Run without a window (a replay never opens one; kept for scripts)");
  std::string video;
  int fps = 25;
  RunOptions video_options;
  video_options.width = 640;
  video_options.height = 360;
  replay_command->add_option("--video", video,
                             "Render the replay into an Ogg Theora video (needs X, e.g. Xvfb)");
  replay_command->add_option("--fps", fps, "Video frames per simulated second")
      ->check(CLI::Range(1, 120));
  replay_command->add_option("--width", video_options.width, "Video width in pixels")
      ->check(CLI::Range(64, 3840));
  replay_command->add_option("--height", video_options.height, "Video height in pixels")
      ->check(CLI::Range(64, 2160));
  replay_command->add_option("--report", replay_report, "Folder for report.json");
  replay_command->add_flag("--json", replay_json, "Print the report as JSON");
  replay_command->callback(
      [&] { exit_code = replay(trace, replay_report, replay_json, video, fps, video_options); });

  std::string report_json;
  std::string report_reference;
  std::string report_out;
  auto* report_command = app.add_subcommand(
      "report", "Write the HTML page and plots of a session's report.json (needs X, e.g. Xvfb)");
  report_command->add_option("report", report_json, "report.json of a session")->required();
  report_command->add_option("--reference", report_reference,
                             "An expert's report.json to compare against");
  report_command->add_option("--out", report_out,
                             "Folder of the page (default: beside the report)");
  report_command->callback([&] {
    const nlohmann::json json = read_json_file(report_json);
    if (!viscera::core::has_format(json, "viscera-session-report"))
      throw viscera::core::InputError("is not a viscera session report", {report_json, "", ""});
    const fs::path folder =
        report_out.empty() ? fs::absolute(report_json).parent_path() : fs::path(report_out);
    std::cout << "html " << write_html(json, report_reference, folder) << "\n";
    exit_code = 0;
  });

  add_fluid_command(app, exit_code);

  return viscera::cli::run_command_line(app, argc, argv, exit_code);
}
