#pragma once
/// The session report as a page a trainee and trainer read together (seed 000 §11: "a
/// comprehensive report summarizing the quantitative metrics ... used for providing instructive
/// feedback"): report.html beside report.json, with the metrics in total and per step, the
/// tasks and events, and PNG plots (report_plots.h) in the same folder; given an expert's
/// report as reference, every metric is set against the expert's with the better side marked.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace viscera::report {

/// A metric of the report and which way is better.
struct MetricSpec {
  std::string key;     ///< member of "metrics" in report.json
  std::string label;   ///< for the reader
  std::string unit;    ///< shown after the value ("" for a plain number)
  double scale = 1.0;  ///< value × scale is shown (e.g. 100 for fractions in %)
  bool higher_is_better = false;
};

/// The metrics the page shows, in order (seed 000 §11).
const std::vector<MetricSpec>& report_metrics();

/// "better", "worse" or "equal" for a trainee value against the reference's.
std::string compare_metric(const MetricSpec& metric, double trainee, double reference);

/// Writes report.html and the plots it shows (path_xy.png, path_xz.png, force.png,
/// scores.png) into `folder`; returns the files written, the page first. Rendering the plots
/// needs an X server. Throws core::InputError for a report without the members it needs and
/// core::OutputError when a file cannot be written.
std::vector<std::filesystem::path> write_html_report(const nlohmann::json& report,
                                                     const nlohmann::json* reference,
                                                     const std::filesystem::path& folder);

/// The values of every src="…" attribute of `html`, in order.
std::vector<std::string> referenced_images(const std::string& html);

}  // namespace viscera::report
