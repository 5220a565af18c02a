/// `viscera-sim`: the simulator runtime. Opens a scenario package and runs a session on it.
/// Exit codes (DESIGN.md §9): 0 success, 1 internal error, 2 usage, 3 unreadable or invalid
/// input, 4 validation failed.

#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "studio/cli/command_line.h"
#include "core/error.h"
#include "core/package/scenario_package.h"
#include "simulator/session/headless_session.h"

namespace {

namespace fs = std::filesystem;

struct RunOptions {
  std::string package;
  bool headless = false;
  double duration = 0.0;
  std::string report_dir;
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
  const viscera::sim::SessionReport report = viscera::sim::run_headless(scenario, run);
  const nlohmann::json json = viscera::sim::report_to_json(report);

  std::string report_path;
  if (!options.report_dir.empty()) {
    const fs::path path = fs::absolute(options.report_dir) / "report.json";
    write_atomically(path, json.dump(2) + "\n");
    report_path = path.string();
  }
  if (options.json) {
    std::cout << json.dump(2) << "\n";
  } else {
    std::cout << "simulated " << report.simulated_time << " s in " << report.steps << " steps ("
              << report.wall_time << " s wall, " << report.substeps << " substeps per step)\n"
              << "max displacement " << report.max_displacement << " m\n"
              << "final state hash " << report.final_state_hash << "\n";
    if (!report_path.empty()) std::cout << "report " << report_path << "\n";
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
  run_command->add_option("package", options.package, "Package (.vscene folder or .vscz)")->required();
  run_command->add_flag("--headless", options.headless, "Run without a window");
  run_command->add_option("--duration", options.duration, "Simulated seconds (default: the scenario's limit)")
      ->check(CLI::NonNegativeNumber);
  run_command->add_option("--report", options.report_dir, "Folder for report.json");
  run_command->add_flag("--json", options.json, "Print the report as JSON");
  run_command->callback([&] { exit_code = run(options); });

  return viscera::cli::run_command_line(app, argc, argv, exit_code);
}
