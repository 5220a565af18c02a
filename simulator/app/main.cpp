/// `viscera-sim`: the simulator runtime. Opens a scenario package and runs a session on it, or
/// replays a recorded session and checks it bit for bit.
/// Exit codes (DESIGN.md §9): 0 success, 1 internal error, 2 usage, 3 unreadable or invalid
/// input, 4 validation failed (a replay that departs from its recording).

#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include "core/error.h"
#include "core/package/scenario_package.h"
#include "simulator/report/html_report.h"
#include "simulator/session/headless_session.h"
#include "simulator/session/manual_control.h"
#include "simulator/session/session_trace.h"
#include "simulator/view/view_session.h"
#include "studio/cli/command_line.h"

namespace {

namespace fs = std::filesystem;
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
  bool plain_optics = false;  ///< no distortion, depth of field or field stop
  double optics = -1.0;       ///< ° of the angled optics; negative: the script's or scenario's
  bool html = false;          ///< also write report.html with its plots (needs X)
  std::string reference;      ///< an expert's report.json to compare against
};

/// Writes `text` to `path` through a temporary sibling, so a reader never sees half a report.
void write_atomically(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  const fs::path temporary = path.string() + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    if (!out) throw viscera::core::OutputError("cannot write the report", {path.string(), "", ""});
  }
  fs::rename(temporary, path);
}

/// Reads a JSON document; throws core::InputError naming the file.
nlohmann::json read_json_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw viscera::core::InputError("cannot open", {path, "", ""});
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw viscera::core::InputError(
        "not valid JSON (syntax error at byte " + std::to_string(e.byte) + ")", {path, "", ""});
  }
}

/// Writes report.json into `report_dir` (if given) and prints the summary or the JSON.
/// Writes report.html and its plots into `folder` (offscreen VTK charts: needs an X server).
std::string write_html(const nlohmann::json& json, const std::string& reference,
                       const fs::path& folder) {
  nlohmann::json expert;
  if (!reference.empty()) {
    expert = read_json_file(reference);
    if (!expert.is_object() || expert.value("format", std::string()) != "viscera-session-report")
      throw viscera::core::InputError("is not a viscera session report", {reference, "", ""});
  }
  const auto written =
      viscera::report::write_html_report(json, reference.empty() ? nullptr : &expert, folder);
  return written.front().string();
}

void publish(const SessionReport& report, const std::string& report_dir, bool as_json,
             bool html = false, const std::string& reference = "") {
  const nlohmann::json json = viscera::sim::report_to_json(report);
  std::string report_path;
  if (!report_dir.empty()) {
    const fs::path path = fs::absolute(report_dir) / "report.json";
    write_atomically(path, json.dump(2) + "\n");
    report_path = path.string();
    if (html) report_path += "\nhtml " + write_html(json, reference, path.parent_path());
  }
  if (as_json) {
    std::cout << json.dump(2) << "\n";
    return;
  }
  std::cout << "simulated " << report.simulated_time << " s in " << report.steps << " steps ("
            << report.wall_time << " s wall, " << report.substeps << " substeps per step)\n"
            << "max displacement " << report.max_displacement << " m\n";
  if (report.has_instrument) {
    std::cout << "instrument path " << report.metrics.path_length() << " m, "
              << report.metrics.contacts() << " contacts, max force " << report.metrics.max_force()
              << " N, surface seen " << 100.0 * report.metrics.surface_seen() << " %, score "
              << report.score << "\n";
  }
  for (const auto& task : report.tasks) {
    std::cout << "task " << task.id << ": " << task.status
              << (task.note.empty() ? "" : " (" + task.note + ")") << "\n";
  }
  std::cout << "ended: " << report.end_reason << "\n";
  for (const auto& event : report.events)
    std::cout << event.time << " s  " << event.kind << ": " << event.message << "\n";
  std::cout << "final state hash " << report.final_state_hash << "\n";
  if (!report_path.empty()) std::cout << "report " << report_path << "\n";
}

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
                                                         const RunOptions& options,
                                                         bool offscreen) {
  viscera::view::ViewOptions view;
  view.width = options.width;
  view.height = options.height;
  view.offscreen = offscreen;
  view.lens_effects = !options.plain_optics;
  if (!offscreen) view.bindings = viscera::sim::ManualControl::bindings_text();
  return std::make_unique<viscera::view::EndoscopicView>(scenario, package, view);
}

int run(const RunOptions& options) {
  if (options.headless && !options.snapshot.empty()) {
    throw viscera::core::UsageError(
        "--snapshot renders the endoscopic view, which a --headless session never opens");
  }
  viscera::core::Scenario scenario = viscera::core::read_package(options.package);
  // The optics: --optics, else the script's "optics_angle", else the scenario's instrument.
  if (options.optics >= 0.0) {
    scenario.session.instrument.optics_angle = options.optics;
  } else if (!options.script.empty()) {
    const nlohmann::json stated = read_json_file(options.script);
    if (stated.is_object() && stated.contains("optics_angle") && stated["optics_angle"].is_number())
      scenario.session.instrument.optics_angle = stated["optics_angle"].get<double>();
  }
  viscera::sim::HeadlessRunOptions run;
  run.package = fs::absolute(options.package).string();
  run.duration = options.duration > 0.0 ? options.duration : scenario.session.duration_limit;
  std::optional<viscera::sim::ScriptedTrajectory> script;
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
  }
  run.record_inputs = !options.record.empty() || !options.report_dir.empty() || !options.headless;
  SessionReport report;
  if (options.headless) {
    report = viscera::sim::run_headless(scenario, run);
  } else if (!options.snapshot.empty()) {
    // Without a script the instrument rests at the starting pose, where the trainee would
    // begin.
    std::optional<viscera::sim::RecordedInput> resting;
    if (!script) {
      resting.emplace(std::vector<std::pair<long long, viscera::sim::InstrumentState>>{
          {0, viscera::sim::starting_pose(scenario, optics_angle)}});
      run.instrument = &*resting;
    }
    auto view = make_view(scenario, run.package, options, true);
    report = viscera::view::run_with_snapshot(scenario, run, *view, options.snapshot,
                                              options.snapshot_time);
  } else {
    // The trainee drives the instrument from the keyboard and mouse, starting where the
    // scenario's first landmark can be seen, unless a script drives it.
    auto view = make_view(scenario, run.package, options, false);
    std::optional<viscera::sim::ManualControl> manual;
    if (!script) manual.emplace(viscera::sim::starting_pose(scenario, optics_angle));
    report = viscera::view::run_in_window(scenario, run, *view, manual ? &*manual : nullptr);
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
    if (!json.is_object() || json.value("format", std::string()) != "viscera-session-report")
      throw viscera::core::InputError("is not a viscera session report", {report_json, "", ""});
    const fs::path folder =
        report_out.empty() ? fs::absolute(report_json).parent_path() : fs::path(report_out);
    std::cout << "html " << write_html(json, report_reference, folder) << "\n";
    exit_code = 0;
  });

  return viscera::cli::run_command_line(app, argc, argv, exit_code);
}
