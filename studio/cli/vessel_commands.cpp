#include "studio/cli/vessel_commands.h"

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "core/error.h"
#include "core/image/image_volume_io.h"
#include "core/lsystem/lsystem.h"
#include "core/package/scenario_package.h"
#include "core/package/vtk_mesh_io.h"
#include "importers/mesh_reader.h"
#include "studio/cli/command_output.h"
#include "studio/cli/terminal_progress.h"
#include "templates/vessels/cco_vessel_generator.h"
#include "templates/vessels/lsystem_vessel_tree.h"
#include "templates/vessels/spline_vessel_tree.h"
#include "templates/vessels/vessel_pipe_mesh.h"
#include "templates/vessels/vessel_tree_analysis.h"
#include "templates/vessels/vessel_tree_json.h"
#include "textures/png_io.h"

namespace viscera::cli {
namespace {

struct VesselOptions {
  std::string domain, object, units = "m", method = "cco", grammar_file, splines_file;
  std::string output, mesh;
  int terminals = 250, label = 0, generations = 7;
  std::uint64_t seed = 1;
  double flow = 2.5e-6, root_radius = 0.0, voxel = 0.0;
  bool json = false;
};

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw core::InputError("cannot read the file", {path, "", ""});
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool has_extension(const std::filesystem::path& path,
                   std::initializer_list<const char*> extensions) {
  std::string ext = path.extension().string();
  for (auto& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* e : extensions) {
    if (ext == e) return true;
  }
  return false;
}

/// The organ: a label map (.vti), a package's object surface, or a surface mesh file.
std::unique_ptr<templates::PerfusionDomain> load_domain(const VesselOptions& o, std::string& host) {
  const std::filesystem::path path = o.domain;
  if (has_extension(path, {".vti"})) {
    return std::make_unique<templates::LabelMapDomain>(core::read_label_map_vti(path), o.label,
                                                       o.domain);
  }
  if (has_extension(path, {".vscene", ".vscz"})) {
    const core::Scenario scenario = core::read_package(path);
    for (const auto& object : scenario.objects) {
      if (o.object.empty() ? object.role == core::ObjectRole::Organ : object.id == o.object) {
        host = object.id;
        return std::make_unique<templates::SurfaceMeshDomain>(object.surface,
                                                              o.domain + ":" + object.id);
      }
    }
    throw core::InputError(
        o.object.empty() ? "the package has no organ" : "no object \"" + o.object + "\"",
        {o.domain, "", ""});
  }
  core::SurfaceMesh surface;
  if (has_extension(path, {".vtp"})) {
    core::SurfaceEmbedding unused;
    core::read_surface_vtp(path, surface, unused);
  } else {
    surface = importers::read_mesh(path, importers::length_unit_from_string(o.units));
  }
  return std::make_unique<templates::SurfaceMeshDomain>(std::move(surface), o.domain);
}

core::VesselTree make_tree(const VesselOptions& o, const templates::PerfusionDomain* domain,
                           core::Progress& progress) {
  if (o.method == "cco") {
    if (!domain) throw core::UsageError("--method cco needs --domain");
    templates::CcoOptions options;
    options.terminals = o.terminals;
    options.seed = o.seed;
    options.perfusion_flow = o.flow;
    return templates::grow_cco_tree(*domain, options, progress);
  }
  if (o.method == "lsystem") {
    const std::string grammar_text =
        o.grammar_file.empty() ? templates::kDefaultVesselGrammar : read_text_file(o.grammar_file);
    const auto grammar = core::Lsystem::parse(
        grammar_text, o.grammar_file.empty() ? "built-in grammar" : o.grammar_file);
    templates::LsystemVesselOptions options;
    options.generations = o.generations;
    options.seed = o.seed;
    options.total_flow = o.flow;
    options.turtle.seed = o.seed;
    options.turtle.angle_jitter = 8.0;
    options.domain = domain;
    if (domain) {
      // Start at the inlet, heading into the organ, with the first branch a quarter of its size.
      const auto box = domain->bounds();
      options.turtle.origin = domain->default_inlet();
      const core::Vec3 inward = (box.center() - options.turtle.origin).normalized();
      options.turtle.heading = inward.allFinite() ? inward : core::Vec3::UnitZ();
      options.turtle.left = options.turtle.heading.unitOrthogonal();
      options.turtle.step = 0.25 * box.size().minCoeff();
    } else {
      options.turtle.heading = core::Vec3::UnitZ();
      options.turtle.left = core::Vec3::UnitX();
      options.turtle.step = 0.02;
    }
    if (o.root_radius > 0.0) options.root_radius = o.root_radius;
    return templates::lsystem_vessel_tree(grammar, options);
  }
  if (o.method == "splines") {
    if (o.splines_file.empty())
      throw core::UsageError("--method splines needs --splines FILE.json");
    nlohmann::json json;
    try {
      json = nlohmann::json::parse(read_text_file(o.splines_file));
    } catch (const nlohmann::json::parse_error& e) {
      throw core::InputError(std::string("not JSON: ") + e.what(), {o.splines_file, "", ""});
    }
    std::vector<templates::SplineVesselBranch> branches;
    try {
      branches = templates::spline_branches_from_json(json);
    } catch (const core::ValidationError& e) {
      throw core::InputError(e.reason(), {o.splines_file, e.location().json_pointer, ""});
    }
    templates::SplineVesselOptions options;
    options.total_flow = o.flow;
    if (o.root_radius > 0.0) options.root_radius = o.root_radius;
    return templates::spline_vessel_tree(branches, options);
  }
  throw core::UsageError("--method must be cco, lsystem or splines, got \"" + o.method + "\"");
}

void run(const VesselOptions& o) {
  if (o.output.empty()) throw core::UsageError("-o OUT.json is required");
  std::unique_ptr<templates::PerfusionDomain> domain;
  std::string host = o.object;
  if (!o.domain.empty()) domain = load_domain(o, host);
  TerminalProgress bar;
  core::VesselTree tree = make_tree(o, domain.get(), bar.progress());
  tree.host_object = host;

  // Everything goes to temporary names first and is renamed only when all of it succeeded.
  const std::filesystem::path json_path = o.output;
  const std::string json_text = templates::vessel_tree_to_json(tree).dump(2) + "\n";
  std::filesystem::path mesh_temporary;
  std::size_t triangles = 0;
  if (!o.mesh.empty()) {
    templates::PipeMeshOptions mesh_options;
    mesh_options.voxel_size = o.voxel;
    const core::SurfaceMesh pipes = templates::vessel_pipe_mesh(tree, mesh_options, bar.progress());
    triangles = pipes.triangles.size();
    mesh_temporary = o.mesh + ".partial.vtp";
    core::write_surface_vtp(pipes, {}, mesh_temporary);
  }
  try {
    textures::write_file_atomically(json_text, json_path);
  } catch (...) {
    std::error_code ignored;
    if (!mesh_temporary.empty()) std::filesystem::remove(mesh_temporary, ignored);
    throw;
  }
  if (!mesh_temporary.empty()) {
    std::error_code ec;
    std::filesystem::rename(mesh_temporary, o.mesh, ec);
    if (ec) throw core::OutputError("cannot rename into place: " + ec.message(), {o.mesh, "", ""});
  }

  const auto issues = templates::validate_vessel_tree(tree);
  const auto json = templates::vessel_tree_to_json(tree)["summary"];
  if (o.json) {
    nlohmann::json out = {{"tree", std::filesystem::absolute(json_path).string()},
                          {"summary", json}};
    if (!o.mesh.empty())
      out["mesh"] = {{"file", std::filesystem::absolute(o.mesh).string()},
                     {"triangles", triangles}};
    print_json(out);
  } else {
    std::ostringstream text;
    text << "wrote " << std::filesystem::absolute(json_path).string() << " (" << json["segments"]
         << " segments, " << json["terminals"] << " terminals)\n";
    if (!o.mesh.empty())
      text << "wrote " << std::filesystem::absolute(o.mesh).string() << " (" << triangles
           << " triangles)\n";
    print_text(text.str());
  }
  // A drawn tree may break the checks; the result is written and the exit code says so.
  if (!issues.empty()) {
    throw core::ValidationError(
        issues.front().message +
            (issues.size() > 1 ? " (and " + std::to_string(issues.size() - 1) + " more)" : ""),
        {o.output, "/tree" + issues.front().json_pointer, ""});
  }
}

}  // namespace

void add_vessel_commands(CLI::App& app) {
  auto* vessels =
      app.add_subcommand("vessels", "Grow or draw a vessel tree (Murray radii, no touching walls)");
  auto o = std::make_shared<VesselOptions>();
  vessels->add_option(
      "--domain,-d", o->domain,
      "Organ: label map (.vti), package (.vscene/.vscz, see --object) or surface mesh");
  vessels->add_option("--terminals,-n", o->terminals, "Terminal segments (cco)")
      ->capture_default_str();
  vessels->add_option("--seed", o->seed, "Random seed")->capture_default_str();
  vessels->add_option("-o,--output", o->output, "Output tree JSON");
  vessels->add_option("--mesh", o->mesh, "Also write the pipe surface (.vtp)");
  vessels->add_option("--method", o->method, "cco, lsystem or splines")->capture_default_str();
  vessels->add_option("--label", o->label, "Label of the organ in a label map (0 = any)")
      ->capture_default_str();
  vessels->add_option("--object", o->object,
                      "Object of a package to grow in (default: first organ)");
  vessels->add_option("--units", o->units, "Unit of a mesh file: m, cm or mm")
      ->capture_default_str();
  vessels->add_option("--grammar", o->grammar_file,
                      "L-system grammar file (lsystem; default built in)");
  vessels->add_option("--generations", o->generations, "L-system generations")
      ->capture_default_str();
  vessels->add_option("--splines", o->splines_file, "Branches as JSON (splines)");
  vessels->add_option("--flow", o->flow, "Root flow in m^3/s")->capture_default_str();
  vessels->add_option("--root-radius", o->root_radius, "Root radius in m (lsystem, splines)");
  vessels->add_option("--voxel", o->voxel, "Voxel size of the pipe mesh in m (0 = automatic)");
  vessels->add_flag("--json", o->json, "Print JSON");
  vessels->callback([o] { run(*o); });
}

}  // namespace viscera::cli
