#include "simulator/app/session_output.h"

#include <fstream>
#include <iostream>

#include "core/error.h"
#include "core/json_text.h"
#include "simulator/report/html_report.h"

namespace viscera::app {

namespace fs = std::filesystem;
using viscera::sim::SessionReport;

namespace {
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

}  // namespace

/// Writes report.json into `report_dir` (if given) and prints the summary or the JSON.
/// Writes report.html and its plots into `folder` (offscreen VTK charts: needs an X server).
std::string write_html(const nlohmann::json& json, const std::string& reference,
                       const fs::path& folder) {
  nlohmann::json expert;
  if (!reference.empty()) {
    expert = viscera::core::read_json_file(reference);
    if (!core::has_format(expert, "viscera-session-report"))
      throw viscera::core::InputError("is not a viscera session report", {reference, "", ""});
  }
  const auto written =
      viscera::report::write_html_report(json, reference.empty() ? nullptr : &expert, folder);
  return written.front().string();
}

void publish(const SessionReport& report, const std::string& report_dir, bool as_json, bool html,
             const std::string& reference) {
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
              << " N, surface seen " << 100.0 * report.metrics.surface_seen() << " %\n";
  }
  if (report.score)
    std::cout << "score " << *report.score << "\n";
  else
    std::cout << "score: not assessed (" << report.score_reason << ")\n";
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

}  // namespace viscera::app
