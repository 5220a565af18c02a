#pragma once
/// What `viscera-sim` writes after a session: report.json (atomically), report.html with its
/// plots, and the summary on standard output.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "simulator/session/session_report.h"

namespace viscera::app {

/// Writes report.html and its plots into `folder` (offscreen VTK charts: needs an X server),
/// compared with the expert's report.json at `reference` when given; returns the page's path.
std::string write_html(const nlohmann::json& json, const std::string& reference,
                       const std::filesystem::path& folder);

/// Writes report.json into `report_dir` (if given; with report.html when `html`) and prints
/// the summary, or the JSON when `as_json`.
void publish(const sim::SessionReport& report, const std::string& report_dir, bool as_json,
             bool html = false, const std::string& reference = "");

}  // namespace viscera::app
