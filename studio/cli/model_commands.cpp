#include "studio/cli/model_commands.h"

#include <filesystem>
#include <sstream>

#include "core/error.h"
#include "core/library/asset_library.h"
#include "core/materials/material_file.h"
#include "core/materials/shipped_materials.h"
#include "core/modelling/model_scene.h"
#include "studio/cli/cli_files.h"
#include "studio/cli/command_output.h"
#include "studio/cli/model_files.h"
#include "studio/cli/model_output_commands.h"
#include "studio/cli/terminal_progress.h"

namespace viscera::cli {
namespace {

namespace fs = std::filesystem;

struct ModelOptions {
  std::string kind, model, other, id, name, role = "organ", output, group, library;
  std::string center = "0,0,0", origin, u_edge, v_edge, to, start_cap = "flat", end_cap = "flat";
  std::string mode = "offset", body = "tets", material_file, shipped, from_library;
  std::vector<std::string> points;
  std::vector<double> radii;
  double radius = 0.0, thickness = 0.003, attach = 1.0, cell_size = 0.0, distance = 0.0;
  double stiffness = 100.0, blend = 0.6;
  int control_level = 0, subdivisions = 4, rows = 4, cols = 4, steps = 6, ring_segments = 32;
  int point = -1, parent = 0, layers = 1;
  bool open = false, none = false, json = false;
};

/// Where an edit goes: -o, or back into the model file.
std::string edit_target(const ModelOptions& o) {
  return o.output.empty() ? o.model : o.output;
}

void create(const ModelOptions& o, const CLI::App& command) {
  core::ModelDocument m;
  m.kind = core::model_kind_from_string(o.kind);
  m.id = o.id.empty() ? o.kind : o.id;
  m.name = o.name.empty() ? m.id : o.name;
  m.role = core::object_role_from_string(o.role);
  const auto refuse = [&](std::initializer_list<const char*> options) {
    for (const char* option : options)
      if (command.count(option) > 0)
        throw core::UsageError(std::string(option) + " does not apply to a " + o.kind);
  };
  switch (m.kind) {
    case core::ModelKind::Ball:
      refuse({"--origin", "--u-edge", "--v-edge", "--point", "--radii"});
      if (!(o.radius > 0.0)) throw core::UsageError("a ball needs --radius R (m)");
      m.ball = core::make_ball(parse_point(o.center, "--center"), o.radius, o.control_level,
                               o.subdivisions);
      break;
    case core::ModelKind::Flat:
      refuse({"--center", "--radius", "--point", "--radii"});
      if (o.origin.empty() || o.u_edge.empty() || o.v_edge.empty())
        throw core::UsageError("a flat needs --origin, --u-edge and --v-edge (x,y,z in m)");
      m.flat = core::make_flat(parse_point(o.origin, "--origin"), parse_point(o.u_edge, "--u-edge"),
                               parse_point(o.v_edge, "--v-edge"), o.rows, o.cols, o.thickness);
      m.flat.open = o.open;
      m.flat.steps_per_patch = o.steps;
      break;
    case core::ModelKind::Pipe: {
      refuse({"--center", "--origin", "--u-edge", "--v-edge"});
      const auto points = parse_points(o.points, "--point");
      std::vector<double> radii = o.radii;
      if (radii.empty() && o.radius > 0.0) radii.assign(points.size(), o.radius);
      if (radii.size() == 1) radii.assign(points.size(), radii.front());
      m.pipe = core::make_pipe_network(points, radii);
      m.pipe.start_cap = core::pipe_cap_from_string(o.start_cap);
      m.pipe.end_cap = core::pipe_cap_from_string(o.end_cap);
      m.pipe.ring_segments = o.ring_segments;
      m.pipe.blend = o.blend;
      break;
    }
  }
  save_model(m, o.output);
  print_text("wrote " + fs::absolute(o.output).string() + " (" + o.kind + " \"" + m.id + "\", " +
             std::to_string(core::model_control_points(m).size()) + " control points)\n");
}

void list_points(const ModelOptions& o) {
  const core::ModelDocument m = load_model(o.model);
  const auto points = core::model_control_points(m);
  if (o.json) {
    print_json({{"model", m.id},
                {"kind", core::to_string(m.kind)},
                {"points", [&] {
                   nlohmann::json list = nlohmann::json::array();
                   for (const auto& p : points)
                     list.push_back({p.x(), p.y(), p.z()});
                   return list;
                 }()}});
    return;
  }
  std::ostringstream out;
  out.precision(17);
  for (std::size_t i = 0; i < points.size(); ++i)
    out << i << "  " << points[i].x() << "," << points[i].y() << "," << points[i].z() << "\n";
  print_text(out.str());
}

void move_point(const ModelOptions& o) {
  core::ModelDocument m = load_model(o.model);
  const core::Vec3 to = parse_point(o.to, "--to");
  const auto before = core::model_control_points(m);
  core::move_model_control_point(m, o.point, to);  // checks the index
  const core::Vec3 from = before[static_cast<std::size_t>(o.point)];
  // The new shape must still tessellate (a pipe that folds, a sheet that inverts is refused
  // here, not later in the package step).
  core::tessellate_model(m);
  save_model(m, edit_target(o));
  print_text("moved point " + std::to_string(o.point) + " of \"" + m.id + "\" by " +
             std::to_string((to - from).norm()) + " m\n");
}

void branch(const ModelOptions& o) {
  core::ModelDocument m = load_model(o.model);
  core::PipeBranch b;
  b.points = parse_points(o.points, "--point");
  b.radii = o.radii;
  if (b.radii.empty() && o.radius > 0.0) b.radii.assign(b.points.size(), o.radius);
  if (b.radii.size() == 1) b.radii.assign(b.points.size(), b.radii.front());
  b.parent = o.parent;
  b.attach = o.attach;
  const int index = core::add_model_branch(m, b);
  save_model(m, edit_target(o));
  print_text("added branch " + std::to_string(index) + " to \"" + m.id + "\" at " +
             std::to_string(o.attach) + " of branch " + std::to_string(o.parent) + "\n");
}

void layer(const ModelOptions& o) {
  core::ModelDocument m = load_model(o.model);
  if (o.none) {
    m.layering.reset();
  } else {
    core::ModelLayering layering;
    layering.layers.layers = o.layers;
    layering.layers.thickness = o.thickness;
    layering.layers.mode = core::layer_mode_from_string(o.mode);
    if (o.body != "tets" && o.body != "mass-spring")
      throw core::UsageError("--body is tets or mass-spring, not \"" + o.body + "\"");
    layering.mass_spring = o.body == "mass-spring";
    layering.cell_size = o.cell_size;
    m.layering = layering;
    // The copies must not fold: checked now on the surface, not at packaging.
    core::layer_positions(core::tessellate_model(m), layering.layers);
  }
  save_model(m, edit_target(o));
  print_text(o.none ? "\"" + m.id + "\" has no layers\n"
                    : "\"" + m.id + "\": " + std::to_string(o.layers) + " layers, " + o.body +
                          " body\n");
}

void set_material(const ModelOptions& o) {
  core::ModelDocument m = load_model(o.model);
  const int sources = !o.material_file.empty() + !o.shipped.empty() + !o.from_library.empty();
  if (sources != 1)
    throw core::UsageError("give exactly one of --file, --shipped and --from-library");
  if (!o.material_file.empty()) {
    m.material = core::material_from_file_json(read_json_file(o.material_file), o.material_file);
  } else if (!o.shipped.empty()) {
    m.material = core::shipped_material(o.shipped);
  } else {
    const core::AssetLibrary library(core::resolve_library_path(o.library));
    const core::AssetEntry entry = library.get(o.from_library);
    const std::string where = library.path().string() + ":" + o.from_library;
    if (entry.summary.type != core::AssetType::Material)
      throw core::InputError(
          "the entry is a " + core::to_string(entry.summary.type) + ", not a material",
          {library.path().string(), "", o.from_library});
    nlohmann::json json;
    try {
      json = nlohmann::json::parse(entry.payload);
    } catch (const nlohmann::json::parse_error&) {
      throw core::InputError("the material entry is not JSON", {where, "", ""});
    }
    m.material = core::material_from_file_json(json, where);
  }
  save_model(m, edit_target(o));
  print_text("\"" + m.id + "\" is made of " + m.material->id + "\n");
}

void fix(const ModelOptions& o) {
  core::ModelDocument m = load_model(o.model);
  m.fixed.push_back({parse_point(o.center, "--center"), o.radius});
  save_model(m, edit_target(o));
  print_text("\"" + m.id + "\" has " + std::to_string(m.fixed.size()) + " fixed regions\n");
}

void connect(const ModelOptions& o) {
  core::ModelDocument a = load_model(o.model);
  core::ModelDocument b = load_model(o.other);
  a.connections.erase(std::remove_if(a.connections.begin(), a.connections.end(),
                                     [&](const auto& c) { return c.object == b.id; }),
                      a.connections.end());
  a.connections.push_back({b.id, o.distance, o.stiffness});
  if (!o.group.empty()) a.group = b.group = o.group;
  core::check_model(a);
  // Build both bodies now so the user learns at once how many knots meet.
  TerminalProgress bar;
  // Only this connection is resolved: the others may name models not given here.
  core::ModelDocument only_a = a, only_b = b;
  only_a.connections = {a.connections.back()};
  only_b.connections.clear();
  const core::Scenario scenario = core::build_model_scenario({only_a, only_b}, bar.progress());
  const std::size_t pairs = scenario.connections.front().node_pairs.size();
  save_model(a, o.model);
  if (!o.group.empty()) save_model(b, o.other);
  if (o.json) {
    print_json({{"object_a", a.id},
                {"object_b", b.id},
                {"distance", o.distance},
                {"node_pairs", pairs},
                {"group", a.group}});
  } else {
    print_text("connected \"" + a.id + "\" and \"" + b.id + "\" at " + std::to_string(pairs) +
               " knot pairs within " + std::to_string(o.distance) + " m\n");
  }
}

}  // namespace

void add_model_commands(CLI::App& app) {
  auto* model = app.add_subcommand(
      "model", "Model objects from KisMo's ball, flat and pipe types (seed 001 §3.3)");
  model->require_subcommand(1);
  auto o = std::make_shared<ModelOptions>();

  auto* create_command = model->add_subcommand("new", "Create a ball, flat or pipe model");
  create_command->add_option("kind", o->kind, "ball, flat or pipe")->required();
  create_command->add_option("-o,--output", o->output, "Output model JSON")->required();
  create_command->add_option("--id", o->id, "Object id (default: the kind)");
  create_command->add_option("--name", o->name, "Object name");
  create_command->add_option("--role", o->role, "organ, pathology, vessel or fixture")
      ->capture_default_str();
  create_command->add_option("--center", o->center, "Ball centre x,y,z (m)");
  create_command->add_option("--radius", o->radius, "Ball or pipe radius (m)");
  create_command->add_option("--control-level", o->control_level,
                             "Ball control points: 0, 1, 2 (12, 42, 162 points)");
  create_command->add_option("--subdivisions", o->subdivisions, "Ball tessellation level 0-7")
      ->capture_default_str();
  create_command->add_option("--origin", o->origin, "Flat corner x,y,z (m)");
  create_command->add_option("--u-edge", o->u_edge, "Flat edge along the rows x,y,z (m)");
  create_command->add_option("--v-edge", o->v_edge, "Flat edge across the rows x,y,z (m)");
  create_command->add_option("--rows", o->rows, "Flat control rows")->capture_default_str();
  create_command->add_option("--cols", o->cols, "Flat control columns")->capture_default_str();
  create_command->add_option("--thickness", o->thickness, "Flat slab thickness (m)")
      ->capture_default_str();
  create_command->add_flag("--open", o->open, "Flat as an open sheet");
  create_command->add_option("--steps", o->steps, "Flat tessellation steps per patch")
      ->capture_default_str();
  create_command->add_option("--point", o->points, "Pipe centre-line point x,y,z (repeat)");
  create_command->add_option("--radii", o->radii, "Pipe radius per point (m), comma separated")
      ->delimiter(',');
  create_command->add_option("--start-cap", o->start_cap, "Pipe start: flat, round or open")
      ->capture_default_str();
  create_command->add_option("--end-cap", o->end_cap, "Pipe ends: flat, round or open")
      ->capture_default_str();
  create_command->add_option("--ring-segments", o->ring_segments, "Pipe vertices per ring")
      ->capture_default_str();
  create_command->add_option("--blend", o->blend, "Junction fillet as a fraction of the radius")
      ->capture_default_str();
  create_command->callback([o, create_command] { create(*o, *create_command); });

  auto* points_command = model->add_subcommand("points", "List a model's control points");
  points_command->add_option("model", o->model, "Model JSON")->required();
  points_command->add_flag("--json", o->json, "Print JSON");
  points_command->callback([o] { list_points(*o); });

  auto* move_command = model->add_subcommand("move-point", "Move one control point");
  move_command->add_option("model", o->model, "Model JSON")->required();
  move_command->add_option("--point", o->point, "Control point index (see model points)")
      ->required();
  move_command->add_option("--to", o->to, "New position x,y,z (m)")->required();
  move_command->add_option("-o,--output", o->output, "Write here instead of in place");
  move_command->callback([o] { move_point(*o); });

  auto* branch_command = model->add_subcommand("branch", "Add a child branch to a pipe model");
  branch_command->add_option("model", o->model, "Pipe model JSON")->required();
  branch_command->add_option("--parent", o->parent, "Parent branch")->capture_default_str();
  branch_command->add_option("--attach", o->attach, "Where on the parent, 0-1 of its length")
      ->capture_default_str();
  branch_command->add_option("--point", o->points, "Branch point x,y,z (repeat)")->required();
  branch_command->add_option("--radius", o->radius, "Branch radius (m)");
  branch_command->add_option("--radii", o->radii, "Radius per point (m), comma separated")
      ->delimiter(',');
  branch_command->add_option("-o,--output", o->output, "Write here instead of in place");
  branch_command->callback([o] { branch(*o); });

  auto* layer_command = model->add_subcommand("layer", "Layer a model into a volumetric body");
  layer_command->add_option("model", o->model, "Model JSON")->required();
  layer_command->add_option("--layers", o->layers, "Inner copies")->capture_default_str();
  layer_command->add_option("--thickness", o->thickness, "Wall thickness (m)");
  layer_command->add_option("--mode", o->mode, "offset or scale")->capture_default_str();
  layer_command->add_option("--body", o->body, "tets (gmsh) or mass-spring (KisMo)")
      ->capture_default_str();
  layer_command->add_option("--cell-size", o->cell_size, "Tet size (m; default thickness/layers)");
  layer_command->add_flag("--none", o->none, "Remove the layers");
  layer_command->add_option("-o,--output", o->output, "Write here instead of in place");
  layer_command->callback([o, layer_command] {
    if (!o->none && layer_command->count("--thickness") == 0)
      throw core::UsageError("model layer needs --thickness T (m), or --none");
    layer(*o);
  });

  auto* material_command = model->add_subcommand("material", "Give a model its material");
  material_command->add_option("model", o->model, "Model JSON")->required();
  material_command->add_option("--file", o->material_file, "Material JSON (material fit)");
  material_command->add_option("--shipped", o->shipped, "Shipped material id (material list)");
  material_command->add_option("--from-library", o->from_library, "Material entry of the library");
  material_command->add_option("--library", o->library, "Library database");
  material_command->add_option("-o,--output", o->output, "Write here instead of in place");
  material_command->callback([o] { set_material(*o); });

  auto* fix_command = model->add_subcommand("fix", "Hold the body nodes inside a ball still");
  fix_command->add_option("model", o->model, "Model JSON")->required();
  fix_command->add_option("--center", o->center, "Centre x,y,z (m)")->required();
  fix_command->add_option("--radius", o->radius, "Radius (m)")->required();
  fix_command->add_option("-o,--output", o->output, "Write here instead of in place");
  fix_command->callback([o] { fix(*o); });

  auto* connect_command = model->add_subcommand(
      "connect", "Connect model A to model B at their nearest knots within a distance");
  connect_command->add_option("a", o->model, "Model JSON A (gets the connection)")->required();
  connect_command->add_option("b", o->other, "Model JSON B")->required();
  connect_command->add_option("--distance", o->distance, "Largest knot distance (m)")->required();
  connect_command->add_option("--stiffness", o->stiffness, "N/m per knot pair")
      ->capture_default_str();
  connect_command->add_option("--group", o->group, "Put both into this organ group");
  connect_command->add_flag("--json", o->json, "Print JSON");
  connect_command->callback([o] { connect(*o); });

  add_model_output_commands(*model);
}

}  // namespace viscera::cli
