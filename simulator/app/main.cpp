/// `viscera-sim`: the simulator runtime. Opens a scenario package and runs a session on it, or
/// replays a recorded session and checks it bit for bit.
/// Exit codes (DESIGN.md §9): 0 success, 1 internal error, 2 usage, 3 unreadable or invalid
/// input, 4 validation failed (a replay that departs from its recording).

#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include "core/error.h"
#include "core/package/scenario_package.h"
#include "simulator/session/headless_session.h"
#include "simulator/session/session_trace.h"
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
void publish(const SessionReport& report, const std::string& report_dir, bool as_json) {
  const nlohmann::json json = viscera::sim::report_to_json(report);
  std::string report_path;
  if (!report_dir.empty()) {
    const fs::path path = fs::absolute(report_dir) / "report.json";
    write_atomically(path, json.dump(2) + "\n");
    report_path = path.string();
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

int run(const RunOptions& options) {
  if (!options.headless) {
    // The endoscopic view comes with the rendering module; until then every session is
    // headless, and saying so beats opening an empty window.
    std::cerr << "viscera-sim: no view module in this build; running headless\n";
  }
  const viscera::core::Scenario scenario = viscera::core::read_package(options.package);
  viscera::sim::HeadlessRunOptions run;
  run.package = fs::absolute(options.package).string();
  run.duration = options.duration > 0.0 ? options.duration : scenario.session.duration_limit;
  std::optional<viscera::sim::ScriptedTrajectory> script;
  nlohmann::json script_json;
  const double optics_angle = scenario.session.instrument.optics_angle;
  if (!options.script.empty()) {
    script = viscera::sim::ScriptedTrajectory::read(options.script, optics_angle);
    script_json = read_json_file(options.script);
    run.instrument = &*script;
    run.instrument_body = script->body();
    run.instrument_stiffness = script->stiffness();
    run.perforation_depth = script->perforation_depth();
    run.force_warning = script->force_warning();
    if (options.duration <= 0.0) run.duration = script->duration();
  }
  run.record_inputs = !options.record.empty() || !options.report_dir.empty();
  const SessionReport report = viscera::sim::run_headless(scenario, run);
  const viscera::sim::SessionTrace trace =
      make_trace(options, run, script_json, optics_angle, report);
  if (!options.record.empty()) viscera::sim::write_trace(trace, options.record);
  if (!options.report_dir.empty())
    viscera::sim::write_trace(trace, fs::path(options.report_dir) / "trace.json");
  publish(report, options.report_dir, options.json);
  return 0;
}

/// Runs the recorded session again and compares every checkpoint hash.
int replay(const std::string& trace_path, const std::string& report_dir, bool as_json) {
  const viscera::sim::SessionTrace trace = viscera::sim::read_trace(trace_path);
  if (viscera::sim::package_manifest_sha256(trace.package) != trace.manifest_sha256) {
    throw viscera::core::ValidationError("the package changed since the session was recorded",
                                         {trace.package, "", ""});
  }
  const viscera::core::Scenario scenario = viscera::core::read_package(trace.package);
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
  const SessionReport report = viscera::sim::run_headless(scenario, run);
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
  if (!as_json)
    std::cout << "replay identical: " << trace.checkpoints.size() << " checkpoints match\n";
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
  run_command->add_flag("--headless", options.headless, "Run without a window");
  run_command
      ->add_option("--duration", options.duration,
                   "Simulated seconds (default: the script's length or the scenario's limit)")
      ->check(CLI::NonNegativeNumber);
  run_command->add_option("--script", options.script,
                          "Scripted instrument trajectory (viscera-script JSON)");
  run_command->add_option("--record", options.record, "Write the session's trace here for replay");
  run_command->add_option("--report", options.report_dir, "Folder for report.json");
  run_command->add_flag("--json", options.json, "Print the report as JSON");
  run_command->callback([&] { exit_code = run(options); });

  std::string trace;
  std::string replay_report;
  bool replay_json = false;
  bool replay_headless = false;
  auto* replay_command =
      app.add_subcommand("replay", "Replay a recorded session and check it is bit-identical");
  replay_command->add_option("trace", trace, "Trace written by run --record")->required();
  replay_command->add_flag("--headless", replay_headless,
                           "Run without a window (the only mode of this build)");
  replay_command->add_option("--report", replay_report, "Folder for report.json");
  replay_command->add_flag("--json", replay_json, "Print the report as JSON");
  replay_command->callback([&] { exit_code = replay(trace, replay_report, replay_json); });

  return viscera::cli::run_command_line(app, argc, argv, exit_code);
}
