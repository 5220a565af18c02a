#include "studio/cli/export_commands.h"

#include <filesystem>

#include "core/package/scenario_package.h"
#include "exporters/scenario_exporter.h"
#include "studio/cli/command_output.h"
#include "studio/cli/terminal_progress.h"

namespace viscera::cli {
namespace {

struct ExportCommandOptions {
  std::string package, format, output;
  std::vector<std::string> objects;
  bool json = false;
};

void run_export(const ExportCommandOptions& o) {
  const exporters::ExportFormat format = exporters::export_format_from_string(o.format);
  TerminalProgress bar;
  const core::Scenario scenario = core::read_package(o.package, bar.progress());
  const exporters::TextureFiles textures = exporters::read_package_textures(o.package, scenario);
  exporters::ExportOptions options;
  options.objects = o.objects;
  const exporters::ExportReport report =
      exporters::export_scenario(scenario, format, o.output, textures, options, bar.progress());
  nlohmann::json files = nlohmann::json::array();
  for (const auto& file : report.files)
    files.push_back(std::filesystem::absolute(file).string());
  if (o.json) {
    print_json({{"package", o.package},
                {"format", exporters::to_string(format)},
                {"files", files},
                {"objects", report.objects},
                {"triangles", report.triangles},
                {"tets", report.tets},
                {"sanitized_values", report.sanitized_values}});
    return;
  }
  std::string text = "wrote " + files.front().get<std::string>() + " (" +
                     std::to_string(report.objects) + " objects, " +
                     std::to_string(report.triangles) + " triangles, " +
                     std::to_string(report.tets) + " tets)\n";
  for (std::size_t i = 1; i < files.size(); ++i)
    text += "  and " + files[i].get<std::string>() + "\n";
  if (report.sanitized_values > 0) {
    text += "  " + std::to_string(report.sanitized_values) +
            " non-finite or zero normals, UVs or colours were replaced\n";
  }
  print_text(text);
}

}  // namespace

void add_export_commands(CLI::App& app) {
  auto options = std::make_shared<ExportCommandOptions>();
  auto* command =
      app.add_subcommand("export", "Export a package or some of its objects for other tools");
  command->add_option("package", options->package, "Scenario package (.vscene folder or .vscz)")
      ->required();
  command->add_option("--format", options->format, "vtk, gltf, glb, obj, stl, ply, msh or sofa")
      ->required();
  command
      ->add_option("-o,--output", options->output,
                   "Output file: .vtm/.vtp/.vtu, .gltf, .glb, .obj, .stl, .ply, .msh or .scn")
      ->required();
  command->add_option("--object", options->objects, "Export only this object (repeatable)");
  command->add_flag("--json", options->json, "Print JSON");
  command->callback([options] { run_export(*options); });
}

}  // namespace viscera::cli
