#include "studio/cli/mesh_commands.h"

#include <algorithm>
#include <filesystem>

#include "core/mesh/surface_mesh.h"
#include "core/mesh/tet_mesh.h"
#include "exporters/mesh_writer.h"
#include "importers/mesh_reader.h"
#include "studio/cli/command_output.h"
#include "studio/cli/meshing_commands.h"

namespace viscera::cli {
namespace {

struct ConvertOptions {
  std::string input, output, units = "m";
  bool json = false;
};

bool writes_tets(const std::filesystem::path& output) {
  const auto known = exporters::tet_mesh_writer_extensions();
  return std::find(known.begin(), known.end(), output.extension().string()) != known.end();
}

/// A tet mesh goes to a format that holds tets as tets; everything else as its surface.
void convert(const ConvertOptions& o) {
  const auto unit = importers::length_unit_from_string(o.units);
  const std::string name = std::filesystem::path(o.input).stem().string();
  const std::string output = std::filesystem::absolute(o.output).string();
  const bool surface_only_output =
      !writes_tets(o.output) || std::filesystem::path(o.output).extension() == ".vtp";
  if (!surface_only_output && importers::may_hold_tetrahedra(o.input)) {
    try {
      const core::TetMesh body = importers::read_tet_mesh(o.input, unit);
      exporters::write_tet_mesh(body, name, o.output);
      if (o.json) {
        print_json({{"output", output},
                    {"kind", "tetrahedra"},
                    {"nodes", body.nodes.size()},
                    {"tets", body.tets.size()},
                    {"volume_m3", core::total_volume(body)}});
      } else {
        print_text("wrote " + output + " (" + std::to_string(body.tets.size()) + " tetrahedra)\n");
      }
      return;
    } catch (const importers::NoTetrahedraError&) {
      // A surface-only .msh or .vtk: convert its surface below.
    }
  }
  if (std::filesystem::path(o.output).extension() == ".vtu") {
    throw core::UsageError("\"" + o.input +
                           "\" holds no tetrahedra to write as .vtu; write a surface as .vtp");
  }
  const core::SurfaceMesh surface = importers::read_mesh(o.input, unit);
  exporters::write_meshes({{name, &surface}}, o.output);
  const auto box = core::bounds(surface);
  if (o.json) {
    print_json({{"output", output},
                {"kind", "surface"},
                {"vertices", surface.vertices.size()},
                {"triangles", surface.triangles.size()},
                {"area_m2", core::surface_area(surface)},
                {"size_m", {box.size().x(), box.size().y(), box.size().z()}}});
  } else {
    print_text("wrote " + output + " (" + std::to_string(surface.triangles.size()) +
               " triangles)\n");
  }
}

}  // namespace

void add_mesh_commands(CLI::App& app) {
  auto* mesh = app.add_subcommand(
      "mesh", "Meshing of label maps and surfaces, conversion and quality reports");
  mesh->require_subcommand(1);

  auto options = std::make_shared<ConvertOptions>();
  auto* command = mesh->add_subcommand("convert",
                                       "Convert a surface or tetrahedral mesh; formats by "
                                       "extension (tets stay tets in .vtu, .vtk, .msh)");
  command
      ->add_option("input", options->input,
                   "Input mesh (OBJ, STL, PLY, OFF, glTF, gmsh .msh, .vtp, .vtu, .vtk, …)")
      ->required();
  command
      ->add_option("-o,--output", options->output,
                   "Output mesh (.obj .stl .ply .gltf .glb .vtp .vtk .msh .vtu)")
      ->required();
  command->add_option("--units", options->units, "Unit of the input file: m, cm or mm")
      ->capture_default_str();
  command->add_flag("--json", options->json, "Print JSON");
  command->callback([options] { convert(*options); });

  add_mesh_surface_command(*mesh);
  add_mesh_tets_commands(*mesh);
}

}  // namespace viscera::cli
