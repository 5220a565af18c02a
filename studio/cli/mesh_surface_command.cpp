#include <filesystem>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/image/image_volume_io.h"
#include "core/package/vtk_mesh_io.h"
#include "exporters/mesh_writer.h"
#include "exporters/staged_output.h"
#include "importers/meshing/label_crop.h"
#include "importers/meshing/label_surface.h"
#include "studio/cli/command_output.h"
#include "studio/cli/meshing_commands.h"
#include "studio/cli/terminal_progress.h"

namespace viscera::cli {
namespace {

struct SurfaceCommandOptions {
  std::string input, output;
  int label = 0;
  std::size_t triangles = 50000;
  int smoothing_iterations = 20;
  double pass_band = 0.01;
  bool json = false;
};

nlohmann::json repair_json(const importers::SurfaceRepairReport& r) {
  return {{"merged_vertices", r.merged_vertices},
          {"split_non_manifold_vertices", r.split_non_manifold_vertices},
          {"filled_holes", r.filled_holes},
          {"reoriented", r.reoriented}};
}

std::string label_name(const core::LabelMap& labels, int label) {
  const auto it = labels.names.find(label);
  return it != labels.names.end() && !it->second.empty() ? it->second
                                                         : "label_" + std::to_string(label);
}

/// One file holding every label's surface: .vtp merges them and keeps a "label" vertex array,
/// the other formats keep one named part per label.
void write_surfaces(const std::vector<importers::LabelSurface>& surfaces,
                    const core::LabelMap& labels, const std::filesystem::path& output) {
  if (output.extension() != ".vtp") {
    std::vector<std::string> names;
    for (const auto& s : surfaces)
      names.push_back(label_name(labels, s.label));
    std::vector<exporters::NamedSurface> named;
    for (std::size_t i = 0; i < surfaces.size(); ++i)
      named.push_back({names[i], &surfaces[i].mesh});
    exporters::write_meshes(named, output);
    return;
  }
  core::SurfaceMesh all;
  auto& label_of_vertex = all.vertex_attributes["label"];
  for (const auto& s : surfaces) {
    const int offset = static_cast<int>(all.vertices.size());
    all.vertices.insert(all.vertices.end(), s.mesh.vertices.begin(), s.mesh.vertices.end());
    all.normals.insert(all.normals.end(), s.mesh.normals.begin(), s.mesh.normals.end());
    label_of_vertex.insert(label_of_vertex.end(), s.mesh.vertices.size(), s.label);
    for (const auto& t : s.mesh.triangles)
      all.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  exporters::StagedOutput staged(output);
  core::write_surface_vtp(all, {}, staged.main_file());
  staged.commit();
}

void run(const SurfaceCommandOptions& o) {
  const core::LabelMap labels = core::read_label_map_vti(o.input);
  std::vector<int> chosen{o.label};
  if (o.label == 0) {
    chosen = importers::labels_present(labels);
    if (chosen.empty()) {
      throw core::InputError("the label map is empty: no voxel has a label", {o.input, "", ""});
    }
  }
  importers::LabelSurfaceOptions options;
  options.smoothing_iterations = o.smoothing_iterations;
  options.pass_band = o.pass_band;
  options.target_triangles = o.triangles;
  TerminalProgress bar;
  std::vector<importers::LabelSurface> surfaces;
  for (const int label : chosen)
    surfaces.push_back(importers::label_surface(labels, label, options, o.input, bar.progress()));
  write_surfaces(surfaces, labels, o.output);

  const std::string output = std::filesystem::absolute(o.output).lexically_normal().string();
  nlohmann::json list = nlohmann::json::array();
  std::string text = "wrote " + output + "\n";
  for (const auto& s : surfaces) {
    const double area = core::surface_area(s.mesh), volume = core::enclosed_volume(s.mesh);
    list.push_back({{"label", s.label},
                    {"name", label_name(labels, s.label)},
                    {"vertices", s.mesh.vertices.size()},
                    {"triangles", s.mesh.triangles.size()},
                    {"extracted_triangles", s.extracted_triangles},
                    {"area_m2", area},
                    {"volume_m3", volume},
                    {"decimation_retries", s.decimation_retries},
                    {"smoothing_dropped", s.smoothing_dropped},
                    {"repair", repair_json(s.repair)}});
    text += "  label " + std::to_string(s.label) + " (" + label_name(labels, s.label) +
            "): " + std::to_string(s.mesh.triangles.size()) + " triangles, area " +
            std::to_string(area * 1e4) + " cm², volume " + std::to_string(volume * 1e6) + " cm³" +
            (s.repair.any() ? ", repaired" : "") + "\n";
  }
  if (o.json) {
    print_json({{"output", output}, {"surfaces", list}});
  } else {
    print_text(text);
  }
}

}  // namespace

void add_mesh_surface_command(CLI::App& mesh) {
  auto o = std::make_shared<SurfaceCommandOptions>();
  auto* command = mesh.add_subcommand(
      "surface",
      "Label map (.vti) → closed surface per label: discrete flying edges, windowed-sinc "
      "smoothing, quadric decimation; watertight, outward, no self-intersections");
  command->add_option("labels", o->input, "Label map (.vti, uint16 labels)")->required();
  command
      ->add_option("-o,--output", o->output,
                   "Output surface (.vtp .obj .stl .ply .gltf .glb .vtk .msh)")
      ->required();
  command->add_option("--label", o->label, "Only this label (default: one surface per label)")
      ->check(CLI::Range(1, 65535));
  command->add_option("--triangles", o->triangles, "Triangle budget per label (0: no decimation)")
      ->capture_default_str();
  command
      ->add_option("--smoothing-iterations", o->smoothing_iterations,
                   "Windowed-sinc iterations (0: no smoothing)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000));
  command
      ->add_option("--pass-band", o->pass_band,
                   "Windowed-sinc pass band in (0, 2); smaller smooths more")
      ->capture_default_str();
  command->add_flag("--json", o->json, "Print JSON");
  command->callback([o] { run(*o); });
}

}  // namespace viscera::cli
