#include "simulator/report/html_report.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/error.h"
#include "core/json_text.h"
#include "core/xml_text.h"
#include "simulator/report/report_plots.h"
#include "simulator/view/image_files.h"

namespace viscera::report {

namespace {

using nlohmann::json;

std::string number(const json& value, double scale = 1.0, int digits = 3) {
  if (!value.is_number()) return "&ndash;";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value.get<double>() * scale);
  return buffer;
}

std::string text_of(const json& object, const std::string& key) {
  return object.contains(key) && object[key].is_string() ? object[key].get<std::string>() : "";
}

/// "72.5 / 100", or "not assessed: <reason>" when the period has no score.
std::string score_text(const json& period) {
  const json score = period.value("score", json());
  if (score.is_number()) return number(score) + " / 100";
  const std::string reason = text_of(period, "score_reason");
  return "not assessed" + (reason.empty() ? std::string() : ": " + core::xml_escaped(reason));
}

const char* kStyle = R"(<style>
body { font-family: sans-serif; margin: 2em; color: #222; max-width: 70em; }
table { border-collapse: collapse; margin: 1em 0; }
th, td { border: 1px solid #bbb; padding: 0.3em 0.7em; text-align: right; }
th:first-child, td:first-child { text-align: left; }
.better { color: #176b24; font-weight: bold; } .worse { color: #b0201b; font-weight: bold; }
img { max-width: 100%; border: 1px solid #ddd; margin: 0.5em 0; }
.plots { display: grid; grid-template-columns: 1fr 1fr; gap: 1em; }
</style>
)";

}  // namespace

const std::vector<MetricSpec>& report_metrics() {
  static const std::vector<MetricSpec> metrics = {
      {"duration", "Duration", "s", 1.0, false},
      {"path_length", "Path length", "mm", 1000.0, false},
      {"economy_of_movement", "Economy of movement", "%", 100.0, true},
      {"contacts", "Tool-wall collisions", "", 1.0, false},
      {"contact_time", "Wall contact time", "s", 1.0, false},
      {"max_force", "Maximum force", "N", 1.0, false},
      {"mean_contact_force", "Mean contact force", "N", 1.0, false},
      {"surface_seen", "Cavity surface seen", "%", 100.0, true},
      {"view_quality", "View quality (target centred, in range)", "%", 100.0, true},
      {"inflow_open_time", "Inflow valve open", "s", 1.0, false},
      {"distension_fluid_used", "Distension fluid used", "ml", 1.0e6, false},
      {"tasks_completed", "Tasks completed", "", 1.0, true},
  };
  return metrics;
}

std::string compare_metric(const MetricSpec& metric, double trainee, double reference) {
  const double tolerance = 1e-9 * std::max({1.0, std::abs(trainee), std::abs(reference)});
  if (std::abs(trainee - reference) <= tolerance) return "equal";
  return (trainee > reference) == metric.higher_is_better ? "better" : "worse";
}

namespace {

/// The fluid balance and the bleeding (issue 18 §6) as a table, or nothing without either.
std::string fluid_and_bleeding_table(const json& report) {
  const json fluid = report.value("fluid", json());
  const json bleeding = report.value("bleeding", json());
  const json flow = report.value("distension_flow", json());
  if (!fluid.is_object() && !bleeding.is_object()) return {};
  std::ostringstream out;
  constexpr double kMlPerM3 = 1e6, kMmHgPerPa = 1.0 / 133.322;
  out << "<h2>Fluid and bleeding</h2>\n<table>\n";
  const auto row = [&out](const char* label, const json& value, double scale) {
    out << "<tr><td>" << label << "</td><td>" << number(value, scale) << "</td></tr>\n";
  };
  if (fluid.is_object()) {
    row("Distension fluid used (ml)", fluid.value("used", json()), kMlPerM3);
    row("Drained (ml)", fluid.value("drained", json()), kMlPerM3);
    row("Deficit (ml)", fluid.value("deficit", json()), kMlPerM3);
    row("Absorbed through tissue and ostia (ml)", fluid.value("absorbed", json()), kMlPerM3);
    row("Peak cavity pressure (mmHg)", fluid.value("max_pressure", json()), kMmHgPerPa);
    row("Mean cavity pressure (mmHg)", fluid.value("mean_pressure", json()), kMmHgPerPa);
  }
  if (bleeding.is_object()) {
    row("Blood loss into the cavity (ml)", bleeding.value("blood_loss", json()), kMlPerM3);
    row("Intravasated through opened vessels (ml)", bleeding.value("intravasated", json()),
        kMlPerM3);
    row("Bleeding episodes", bleeding.value("episodes", json()), 1.0);
    row("Controlled (coagulated, clipped, clotted)", bleeding.value("controlled", json()), 1.0);
    row("Mean time to control (s)", bleeding.value("mean_time_to_control", json()), 1.0);
  }
  if (flow.is_object()) {
    row("View obscured by blood (s)", flow.value("view_obscured_time", json()), 1.0);
    row("Blood still in the cavity (ml)", flow.value("blood_in_cavity", json()), kMlPerM3);
    row("Blood carried out by the outflow (ml)", flow.value("blood_drained", json()), kMlPerM3);
  }
  out << "</table>\n";
  return out.str();
}

/// The resection loop's work (issue 17 §5) as a table, or nothing when the instrument could not
/// cut: per pathology how much came off and where its chips are, then the cuts and the wall.
std::string resection_table(const json& report) {
  const json cutting = report.value("cutting", json());
  if (!cutting.is_object()) return {};
  std::ostringstream out;
  out << "<h2>Resection</h2>\n<table>\n<tr><th>Pathology</th><th>Resected (%)</th><th>Chips in "
         "the cavity</th><th>Chips retrieved</th><th>Debris</th></tr>\n";
  for (const json& body : cutting.value("pathologies", json::array())) {
    out << "<tr><td>" << core::xml_escaped(text_of(body, "body")) << "</td><td>"
        << number(body.value("resected_fraction", json()), 100.0) << "</td><td>"
        << number(body.value("chips", json())) << "</td><td>"
        << number(body.value("chips_retrieved", json())) << "</td><td>"
        << number(body.value("debris", json())) << "</td></tr>\n";
  }
  out << "</table>\n<table>\n";
  const auto row = [&out](const char* label, const json& value, double scale) {
    out << "<tr><td>" << label << "</td><td>" << number(value, scale) << "</td></tr>\n";
  };
  constexpr double kMm = 1e3, kMm3 = 1e9;
  row("Cuts", cutting.value("cuts", json()), 1.0);
  row("Sweeps released inside a pathology (not cut)", cutting.value("released_in_tissue", json()),
      1.0);
  row("Median time per cut (ms)", cutting.value("cut_time_median", json()), kMm);
  row("Deepest cut into the wall (mm)", cutting.value("deepest_wall_cut", json()), kMm);
  row("Wall thickness there (mm)", cutting.value("wall_thickness_at_deepest_cut", json()), kMm);
  row("Healthy wall removed (mm³)", cutting.value("healthy_wall_removed", json()), kMm3);
  out << "</table>\n";
  return out.str();
}

}  // namespace

std::vector<std::filesystem::path> write_html_report(const json& report, const json* reference,
                                                     const std::filesystem::path& folder) {
  if (!core::has_format(report, "viscera-session-report"))
    throw core::InputError("is not a viscera session report",
                           {(folder / "report.json").string(), "", ""});
  std::vector<std::filesystem::path> written;
  const std::filesystem::path page = folder / "report.html";
  written.push_back(page);
  for (const char* name : {"path_xy.png", "path_xz.png", "force.png", "scores.png"})
    written.push_back(folder / name);
  plot_tool_path(report, reference, "xy", folder / "path_xy.png");
  plot_tool_path(report, reference, "xz", folder / "path_xz.png");
  plot_force(report, reference, folder / "force.png");
  plot_step_scores(report, reference, folder / "scores.png");
  const bool fluid_plot =
      report.contains("fluid_series") && plot_fluid(report, reference, folder / "fluid.png");
  if (fluid_plot) written.push_back(folder / "fluid.png");

  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
       << "<title>Viscera session report</title>\n"
       << kStyle << "</head><body>\n"
       << "<h1>Session report</h1>\n<table>\n"
       << "<tr><td>Package</td><td>" << core::xml_escaped(text_of(report, "package"))
       << "</td></tr>\n"
       << "<tr><td>Procedure</td><td>" << core::xml_escaped(text_of(report, "procedure"))
       << "</td></tr>\n"
       << "<tr><td>Instrument</td><td>" << core::xml_escaped(text_of(report, "instrument_kind"))
       << "</td></tr>\n"
       << "<tr><td>Simulated time</td><td>"
       << number(report.value("simulated_time", json()), 1.0, 4) << " s</td></tr>\n"
       << "<tr><td>Ended by</td><td>" << core::xml_escaped(text_of(report, "end_reason"))
       << "</td></tr>\n"
       << "<tr><td>Score</td><td>" << score_text(report) << "</td></tr>\n";
  if (reference != nullptr)
    html << "<tr><td>Reference score</td><td>" << score_text(*reference) << "</td></tr>\n";
  html << "</table>\n";

  html << "<h2>Metrics</h2>\n<table>\n<tr><th>Metric</th><th>Trainee</th>";
  if (reference != nullptr) html << "<th>Reference</th><th>Trainee vs reference</th>";
  html << "</tr>\n";
  const json metrics = report.value("metrics", json::object());
  const json expert =
      reference != nullptr ? reference->value("metrics", json::object()) : json::object();
  for (const MetricSpec& m : report_metrics()) {
    const json value = metrics.value(m.key, json());
    html << "<tr><td>" << core::xml_escaped(m.label) << (m.unit.empty() ? "" : " (" + m.unit + ")")
         << "</td><td>" << number(value, m.scale) << "</td>";
    if (reference != nullptr) {
      const json other = expert.value(m.key, json());
      html << "<td>" << number(other, m.scale) << "</td>";
      if (value.is_number() && other.is_number()) {
        const std::string verdict = compare_metric(m, value.get<double>(), other.get<double>());
        html << "<td class=\"" << verdict << "\">" << verdict << "</td>";
      } else {
        html << "<td>&ndash;</td>";
      }
    }
    html << "</tr>\n";
  }
  html << "</table>\n";

  html << "<h2>Plots</h2>\n<div class=\"plots\">\n"
       << "<figure><img src=\"path_xy.png\" alt=\"tool path from above\"><figcaption>Tool path "
          "from above, coloured by the distance to the wall (red: at the "
          "wall).</figcaption></figure>\n"
       << "<figure><img src=\"path_xz.png\" alt=\"tool path from the side\"><figcaption>Tool path "
          "from the side.</figcaption></figure>\n"
       << "<figure><img src=\"force.png\" alt=\"force over time\"><figcaption>Force on the "
          "instrument; dashed: the warning level.</figcaption></figure>\n"
       << "<figure><img src=\"scores.png\" alt=\"scores per step\"><figcaption>Score per step"
       << (reference != nullptr ? " (grey: reference)" : "") << ".</figcaption></figure>\n";
  if (fluid_plot) {
    html << "<figure><img src=\"fluid.png\" alt=\"fluid deficit and blood over time\">"
            "<figcaption>Distension fluid deficit (used − drained) and blood that entered the "
            "cavity.</figcaption></figure>\n";
  }
  html << "</div>\n";
  html << fluid_and_bleeding_table(report);
  html << resection_table(report);

  html << "<h2>Procedure steps</h2>\n<table>\n<tr><th>Step</th><th>Started (s)</th><th>Ended (s)"
          "</th><th>Path (mm)</th><th>Collisions</th><th>Max force (N)</th><th>Seen (%)</th>"
          "<th>Score</th></tr>\n";
  for (const auto& step : report.value("procedure_steps", json::array())) {
    const json m = step.value("metrics", json::object());
    html << "<tr><td>"
         << core::xml_escaped(text_of(step, "name").empty() ? text_of(step, "id")
                                                            : text_of(step, "name"))
         << "</td><td>" << number(step.value("started_at", json())) << "</td><td>"
         << number(step.value("ended_at", json())) << "</td><td>"
         << number(m.value("path_length", json()), 1000.0) << "</td><td>"
         << number(m.value("contacts", json())) << "</td><td>"
         << number(m.value("max_force", json())) << "</td><td>"
         << number(m.value("surface_seen", json()), 100.0) << "</td><td>" << score_text(step)
         << "</td></tr>\n";
  }
  html << "</table>\n<h2>Tasks</h2>\n<table>\n<tr><th>Task</th><th>Status</th><th>Completed at (s)"
          "</th><th>Note</th></tr>\n";
  for (const auto& task : report.value("tasks", json::array())) {
    html << "<tr><td>"
         << core::xml_escaped(text_of(task, "name").empty() ? text_of(task, "id")
                                                            : text_of(task, "name"))
         << "</td><td>" << core::xml_escaped(text_of(task, "status")) << "</td><td>"
         << number(task.value("completed_at", json())) << "</td><td>"
         << core::xml_escaped(text_of(task, "note")) << "</td></tr>\n";
  }
  html << "</table>\n<h2>Events</h2>\n<table>\n<tr><th>Time "
          "(s)</th><th>Event</th><th>Message</th></tr>\n";
  for (const auto& event : report.value("events", json::array())) {
    html << "<tr><td>" << number(event.value("time", json()), 1.0, 4) << "</td><td>"
         << core::xml_escaped(text_of(event, "kind")) << "</td><td>"
         << core::xml_escaped(text_of(event, "message")) << "</td></tr>\n";
  }
  html << "</table>\n</body></html>\n";
  view::write_file_atomically(page, html.str());
  return written;
}

std::vector<std::string> referenced_images(const std::string& html) {
  std::vector<std::string> out;
  const std::string marker = "src=\"";
  for (std::size_t at = html.find(marker); at != std::string::npos; at = html.find(marker, at)) {
    at += marker.size();
    const std::size_t end = html.find('"', at);
    if (end == std::string::npos) break;
    out.push_back(html.substr(at, end - at));
    at = end;
  }
  return out;
}

}  // namespace viscera::report
