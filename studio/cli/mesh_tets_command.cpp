#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/image/image_volume_io.h"
#include "core/mesh/tet_quality.h"
#include "core/meshing/tet_mesher.h"
#include "core/package/vtk_mesh_io.h"
#include "exporters/mesh_writer.h"
#include "exporters/staged_output.h"
#include "importers/mesh_reader.h"
#include "importers/meshing/label_body.h"
#include "studio/cli/command_output.h"
#include "studio/cli/meshing_commands.h"
#include "studio/cli/terminal_progress.h"

namespace viscera::cli {
namespace {

namespace fs = std::filesystem;

struct TetsCommandOptions {
  std::string input, output, units = "m";
  int label = 0;
  double cell_size = 0.0, facet_size = 0.0, facet_distance = 0.0, facet_angle = 30.0;
  double radius_edge_ratio = 3.0, grading = 0.0, sliver_bound = 12.0;
  std::size_t tets = 150000, triangles = 50000;
  std::vector<std::string> label_sizes;
  int threads = 1;
  double time_limit = 300.0;
  std::string surface_source = "tets";
  bool no_exude = false, no_optimize = false, no_surface = false, json = false;
};

struct QualityCommandOptions {
  std::string input;
  double sliver_angle = 5.0;
  bool json = false;
};

std::map<int, double> parse_label_sizes(const std::vector<std::string>& items) {
  std::map<int, double> sizes;
  for (const auto& item : items) {
    const auto eq = item.find('=');
    try {
      if (eq == std::string::npos) throw std::invalid_argument(item);
      sizes[std::stoi(item.substr(0, eq))] = std::stod(item.substr(eq + 1));
    } catch (const std::logic_error&) {
      throw core::UsageError("--label-size takes LABEL=SIZE (SIZE in m), not \"" + item + "\"");
    }
  }
  return sizes;
}

nlohmann::json quality_json(const core::TetMesh& body, const core::TetQualityReport& report) {
  nlohmann::json json = report;
  std::map<std::string, std::size_t> per_label;
  for (const int l : body.tet_labels)
    ++per_label[std::to_string(l)];
  json["tets_per_label"] = per_label;
  return json;
}

std::string quality_text(const core::TetQualityReport& r) {
  const auto fixed = [](double v, int digits) {
    if (!std::isfinite(v)) return std::string("n/a");
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
    return std::string(buffer);
  };
  return "  tets " + std::to_string(r.tets) + ", nodes " + std::to_string(r.nodes) + ", volume " +
         fixed(r.total_volume * 1e6, 3) + " cm³\n  dihedral angles " +
         fixed(r.min_dihedral_degrees, 2) + "° … " + fixed(r.max_dihedral_degrees, 2) +
         "°\n  radius-edge ratio " + fixed(r.min_radius_edge_ratio, 3) + " … " +
         fixed(r.max_radius_edge_ratio, 3) + " (mean " + fixed(r.mean_radius_edge_ratio, 3) +
         ")\n  aspect ratio mean " + fixed(r.mean_aspect_ratio, 3) + ", max " +
         fixed(r.max_aspect_ratio, 3) + "\n  inverted " + std::to_string(r.inverted) +
         ", slivers (< " + fixed(r.sliver_angle_degrees, 1) + "°) " + std::to_string(r.slivers) +
         "\n";
}

bool is_label_map(const fs::path& input) {
  return input.extension() == ".vti";
}

void run_tets(const TetsCommandOptions& o) {
  const fs::path output(o.output);
  const auto writers = exporters::tet_mesh_writer_extensions();
  if (std::find(writers.begin(), writers.end(), output.extension().string()) == writers.end()) {
    throw core::UsageError("write tetrahedra as .vtu, .vtk or .msh, not \"" + o.output + "\"");
  }
  TerminalProgress bar;
  core::TetMesh body;
  core::SurfaceMesh surface;
  core::SurfaceEmbedding embedding;
  core::TetQualityReport quality;
  nlohmann::json criteria;
  std::map<std::string, double> seconds;
  if (is_label_map(o.input)) {
    const core::LabelMap labels = core::read_label_map_vti(o.input);
    importers::LabelBodyOptions options;
    options.tets.label = o.label;
    options.tets.cell_size = o.cell_size;
    options.tets.target_tets = o.tets;
    options.tets.label_cell_size = parse_label_sizes(o.label_sizes);
    options.tets.cell_radius_edge_ratio = o.radius_edge_ratio;
    options.tets.facet_angle_degrees = o.facet_angle;
    options.tets.facet_size = o.facet_size;
    options.tets.facet_distance = o.facet_distance;
    options.tets.exude = !o.no_exude;
    options.tets.exude_sliver_bound_degrees = o.sliver_bound;
    options.tets.threads = o.threads;
    options.surface.target_triangles = o.triangles;
    options.time_limit_seconds = o.time_limit;
    options.visual_surface = o.surface_source == "contour"
                                 ? importers::VisualSurfaceSource::LabelContour
                                 : importers::VisualSurfaceSource::TetBoundary;
    importers::LabelBody made =
        importers::mesh_label_body(labels, options, o.input, bar.progress());
    body = std::move(made.body);
    surface = std::move(made.surface.mesh);
    embedding = std::move(made.embedding);
    quality = made.quality;
    seconds = made.seconds;
    criteria = {{"mesher", "CGAL Mesh_3"},
                {"cell_size_m", made.criteria.cell_size},
                {"facet_size_m", made.criteria.facet_size},
                {"facet_distance_m", made.criteria.facet_distance},
                {"facet_angle_degrees", o.facet_angle},
                {"cell_radius_edge_ratio", o.radius_edge_ratio},
                {"exude_sliver_bound_degrees", o.no_exude ? 0.0 : o.sliver_bound},
                {"threads", o.threads},
                {"visual_surface", o.surface_source}};
  } else {
    surface = importers::read_mesh(o.input, importers::length_unit_from_string(o.units));
    core::TetMeshingOptions options;
    options.cell_size = o.cell_size;
    options.optimize = !o.no_optimize;
    options.grading_distance = o.grading;
    body = core::mesh_closed_surface(surface, options, bar.progress());
    embedding = core::embed_points(surface.vertices, body);
    quality = core::tet_quality(body);
    criteria = {{"mesher", "gmsh"}, {"cell_size_m", o.cell_size}, {"grading_m", o.grading}};
  }

  exporters::StagedOutput staged(output);
  const fs::path surface_name = output.stem().string() + "_surface.vtp";
  if (!o.no_surface) core::write_surface_vtp(surface, embedding, staged.folder() / surface_name);
  exporters::write_tet_mesh(body, output.stem().string(), staged.main_file());
  staged.commit();

  const std::string written = fs::absolute(output).lexically_normal().string();
  const std::string surface_written =
      o.no_surface
          ? std::string()
          : (fs::absolute(output).parent_path() / surface_name).lexically_normal().string();
  if (o.json) {
    print_json(
        {{"output", written},
         {"surface", o.no_surface ? nlohmann::json(nullptr) : nlohmann::json(surface_written)},
         {"surface_triangles", surface.triangles.size()},
         {"embedding_max_error_m", importers::embedding_error(surface, embedding, body)},
         {"criteria", criteria},
         {"seconds", seconds},
         {"quality", quality_json(body, quality)}});
  } else {
    print_text("wrote " + written + " (" + std::to_string(body.tets.size()) + " tetrahedra)\n" +
               (o.no_surface
                    ? std::string()
                    : "wrote " + surface_written + " (visual surface, " +
                          std::to_string(surface.triangles.size()) + " triangles, embedded)\n") +
               quality_text(quality));
  }
  if (!quality.valid()) {
    throw core::ValidationError(std::to_string(quality.inverted) + " tetrahedra are inverted",
                                {o.output, "", ""});
  }
}

void run_quality(const QualityCommandOptions& o) {
  const core::TetMesh body = importers::read_tet_mesh(o.input);
  core::TetQualityOptions options;
  options.sliver_angle_degrees = o.sliver_angle;
  const core::TetQualityReport report = core::tet_quality(body, options);
  if (o.json) {
    print_json(quality_json(body, report));
  } else {
    print_text(o.input + "\n" + quality_text(report));
  }
  if (!report.valid()) {
    throw core::ValidationError(std::to_string(report.inverted) + " tetrahedra are inverted",
                                {o.input, "", ""});
  }
}

}  // namespace

void add_mesh_tets_commands(CLI::App& mesh) {
  auto o = std::make_shared<TetsCommandOptions>();
  auto* tets = mesh.add_subcommand(
      "tets",
      "Label map (.vti) → tets with CGAL Mesh_3, or closed surface → tets with gmsh; writes the "
      "tets, the visual surface embedded in them (OUT_surface.vtp) and prints a quality report");
  tets->add_option("input", o->input, "Label map (.vti) or closed surface (any mesh format)")
      ->required();
  tets->add_option("-o,--output", o->output, "Output tet mesh (.vtu .vtk .msh)")->required();
  tets->add_option("--label", o->label, "Label map: mesh only this label (default: all)")
      ->check(CLI::Range(1, 65535));
  tets->add_option("--cell-size", o->cell_size,
                   "Largest tet circumradius in m (Mesh_3) / target edge length (gmsh); "
                   "0: from --tets (label map) or the surface (gmsh)")
      ->capture_default_str();
  tets->add_option("--tets", o->tets, "Label map: approximate tet count when --cell-size is 0")
      ->capture_default_str();
  tets->add_option("--label-size", o->label_sizes, "Label map: LABEL=SIZE cell size per label, m");
  tets->add_option("--facet-size", o->facet_size,
                   "Label map: largest boundary facet circumradius, m (0: cell size)");
  tets->add_option("--facet-distance", o->facet_distance,
                   "Label map: largest facet-to-boundary distance, m (0: half a voxel)");
  tets->add_option("--facet-angle", o->facet_angle, "Label map: smallest facet angle, degrees")
      ->capture_default_str();
  tets->add_option("--radius-edge-ratio", o->radius_edge_ratio,
                   "Label map: largest cell radius-edge ratio")
      ->capture_default_str();
  tets->add_flag("--no-exude", o->no_exude, "Label map: skip sliver exudation");
  tets->add_option("--exude-bound", o->sliver_bound,
                   "Label map: exudation works on tets whose smallest dihedral angle is below "
                   "this, degrees (0: as far as it goes, slow)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 89.0));
  tets->add_option("--threads", o->threads,
                   "Label map: > 1 runs Mesh_3 in parallel (faster, not bit-reproducible)")
      ->capture_default_str()
      ->check(CLI::Range(1, 256));
  tets->add_option("--surface", o->surface_source,
                   "Label map: visual surface from the tets' boundary (tets: fast, Mesh_3's "
                   "boundary resolution) or the label's smoothed, decimated contour (contour)")
      ->capture_default_str()
      ->check(CLI::IsMember({"tets", "contour"}));
  tets->add_option("--triangles", o->triangles,
                   "Label map, --surface contour: visual surface triangle budget")
      ->capture_default_str();
  tets->add_option("--time-limit", o->time_limit,
                   "Label map: give up (exit 4, nothing written) after this many seconds; 0: never")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  tets->add_option("--grading", o->grading, "Surface: size-field grading distance, m (gmsh)");
  tets->add_flag("--no-optimize", o->no_optimize, "Surface: skip gmsh's optimisation");
  tets->add_option("--units", o->units, "Surface: unit of the input file (m, cm, mm)")
      ->capture_default_str();
  tets->add_flag("--no-surface", o->no_surface, "Do not write the embedded visual surface");
  tets->add_flag("--json", o->json, "Print JSON");
  tets->callback([o] { run_tets(*o); });

  auto q = std::make_shared<QualityCommandOptions>();
  auto* quality = mesh.add_subcommand(
      "quality",
      "Quality report of a tet mesh: dihedral angles, radius-edge and aspect ratios, inverted "
      "and sliver counts (exit 4 when a tet is inverted)");
  quality->add_option("mesh", q->input, "Tet mesh (.vtu .vtk .msh)")->required();
  quality
      ->add_option("--sliver-angle", q->sliver_angle,
                   "Smallest dihedral angle below which a tet is a sliver, degrees")
      ->capture_default_str();
  quality->add_flag("--json", q->json, "Print JSON");
  quality->callback([q] { run_quality(*q); });
}

}  // namespace viscera::cli
