#pragma once
/// The plots of a session report (seed 000 §11 and Fig. 16), rendered offscreen with VTK's
/// charts (vtkContextView + vtkChartXY) into PNG files. They read the report as its JSON
/// (format "viscera-session-report"), so an expert's report.json from an earlier session serves
/// as the reference. Rendering needs an X server (Xvfb), like every VTK window on Debian.

#include <filesystem>
#include <nlohmann/json.hpp>

namespace viscera::report {

/// Pixel size of every plot.
struct PlotSize {
  int width = 820;
  int height = 480;
};

/// The tool path seen from above (`plane` "xy") or from the patient's side ("xz"), each
/// sample coloured by the tip's distance to the wall in mm (seed 000 Fig. 16); the reference
/// path, when given, in grey beneath. Throws core::InputError naming a missing member.
void plot_tool_path(const nlohmann::json& report, const nlohmann::json* reference,
                    const std::string& plane, const std::filesystem::path& png, PlotSize size = {});

/// Force on the instrument (N) over time (s), with the warning level and the reference.
void plot_force(const nlohmann::json& report, const nlohmann::json* reference,
                const std::filesystem::path& png, PlotSize size = {});

/// The distension fluid over time (issue 18 §6): the deficit and the blood that entered the
/// cavity (ml), with the reference's deficit. False, and no file, when the report simulated no
/// fluid (its "fluid_series" is null).
bool plot_fluid(const nlohmann::json& report, const nlohmann::json* reference,
                const std::filesystem::path& png, PlotSize size = {});

/// Score (0…100) of each procedure step and of the whole session, beside the reference's.
void plot_step_scores(const nlohmann::json& report, const nlohmann::json* reference,
                      const std::filesystem::path& png, PlotSize size = {});

}  // namespace viscera::report
