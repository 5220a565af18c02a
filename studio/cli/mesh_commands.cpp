#include "studio/cli/mesh_commands.h"

#include <filesystem>

#include "core/mesh/surface_mesh.h"
#include "exporters/mesh_writer.h"
#include "importers/mesh_reader.h"
#include "studio/cli/command_output.h"

namespace viscera::cli {

void add_mesh_commands(CLI::App& app) {
  auto* mesh = app.add_subcommand("mesh", "Mesh conversion and inspection");
  mesh->require_subcommand(1);

  struct ConvertOptions {
    std::string input, output, units = "m";
    bool json = false;
  };
  auto options = std::make_shared<ConvertOptions>();
  auto* convert = mesh->add_subcommand("convert", "Convert a surface mesh; formats by extension");
  convert->add_option("input", options->input, "Input mesh (OBJ, STL, PLY, OFF, glTF, …)")->required();
  convert->add_option("-o,--output", options->output, "Output mesh (.obj, .stl, .ply)")->required();
  convert->add_option("--units", options->units, "Unit of the input file: m, cm or mm")
      ->capture_default_str();
  convert->add_flag("--json", options->json, "Print JSON");
  convert->callback([options] {
    const core::SurfaceMesh surface =
        importers::read_mesh(options->input, importers::length_unit_from_string(options->units));
    const std::string name = std::filesystem::path(options->input).stem().string();
    exporters::write_meshes({{name, &surface}}, options->output);
    const auto box = core::bounds(surface);
    if (options->json) {
      print_json({{"output", std::filesystem::absolute(options->output).string()},
                  {"vertices", surface.vertices.size()},
                  {"triangles", surface.triangles.size()},
                  {"area_m2", core::surface_area(surface)},
                  {"size_m", {box.size().x(), box.size().y(), box.size().z()}}});
    } else {
      print_text("wrote " + std::filesystem::absolute(options->output).string() + " (" +
                 std::to_string(surface.triangles.size()) + " triangles)\n");
    }
  });
}

}  // namespace viscera::cli
