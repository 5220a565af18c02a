#include "studio/cli/model_output_commands.h"

#include <filesystem>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/mesh/surface_mesh.h"
#include "core/modelling/model_scene.h"
#include "core/modelling/object_connectivity.h"
#include "core/package/scenario_package.h"
#include "core/package/vtk_mesh_io.h"
#include "studio/cli/command_output.h"
#include "studio/cli/model_files.h"
#include "studio/cli/terminal_progress.h"

namespace viscera::cli {
namespace {

namespace fs = std::filesystem;

struct OutputOptions {
  std::vector<std::string> models;
  std::string output, body, name;
  bool json = false;
};

/// Writes through a temporary sibling renamed into place, so a failure leaves nothing.
template <typename Write>
void write_via_temporary(const fs::path& target, const std::string& suffix, Write write) {
  const fs::path temporary = target.string() + ".partial" + suffix;
  try {
    write(temporary);
    fs::rename(temporary, target);
  } catch (const fs::filesystem_error& e) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw core::OutputError(std::string("cannot move into place: ") + e.what(),
                            {target.string(), "", ""});
  } catch (...) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw;
  }
}

nlohmann::json object_summary(const core::SceneObject& object) {
  const bool closed = core::is_closed_and_consistently_oriented(object.surface);
  nlohmann::json json = {{"id", object.id},
                         {"vertices", object.surface.vertices.size()},
                         {"triangles", object.surface.triangles.size()},
                         {"closed", closed},
                         {"area", core::surface_area(object.surface)},
                         {"body", core::to_string(object.body_kind)},
                         {"body_nodes", object.body.nodes.size()},
                         {"body_tets", object.body.tets.size()}};
  json["volume"] = closed ? nlohmann::json(core::enclosed_volume(object.surface)) : nullptr;
  if (!object.body.tets.empty()) json["body_volume"] = core::total_volume(object.body);
  std::size_t fixed = 0;
  for (const auto flag : object.body.fixed)
    fixed += flag;
  json["fixed_nodes"] = fixed;
  return json;
}

void mesh(const OutputOptions& o) {
  const core::ModelDocument model = load_model(o.models.front());
  TerminalProgress bar;
  const core::SceneObject object = core::build_model_object(model, bar.progress());
  if (!o.body.empty() && object.body.tets.empty())
    throw core::UsageError("\"" + model.id + "\" has no body (an open sheet without layers)");
  write_via_temporary(o.output, ".vtp", [&](const fs::path& path) {
    core::write_surface_vtp(object.surface, object.embedding, path);
  });
  if (!o.body.empty()) {
    write_via_temporary(o.body, ".vtu",
                        [&](const fs::path& path) { core::write_body_vtu(object.body, path); });
  }
  nlohmann::json json = object_summary(object);
  json["surface_file"] = fs::absolute(o.output).string();
  if (!o.body.empty()) json["body_file"] = fs::absolute(o.body).string();
  if (o.json) {
    print_json(json);
    return;
  }
  std::ostringstream out;
  out << "wrote " << json["surface_file"].get<std::string>() << " (" << json["triangles"]
      << " triangles, " << (json["closed"].get<bool>() ? "closed" : "open") << ", area "
      << json["area"] << " m^2";
  if (json["closed"].get<bool>()) out << ", volume " << json["volume"] << " m^3";
  out << ")\n";
  if (!o.body.empty())
    out << "wrote " << json["body_file"].get<std::string>() << " (" << json["body"] << " body, "
        << json["body_nodes"] << " nodes, " << json["body_tets"] << " tets)\n";
  print_text(out.str());
}

void package(const OutputOptions& o) {
  std::vector<core::ModelDocument> models;
  for (const auto& path : o.models)
    models.push_back(load_model(path));
  TerminalProgress bar;
  core::Scenario scenario = core::build_model_scenario(models, bar.progress());
  if (!o.name.empty()) scenario.metadata.name = o.name;
  core::write_package(scenario, o.output, bar.progress());
  nlohmann::json objects = nlohmann::json::array();
  for (const auto& object : scenario.objects)
    objects.push_back(object_summary(object));
  nlohmann::json connections = nlohmann::json::array();
  for (const auto& c : scenario.connections)
    connections.push_back({{"id", c.id}, {"node_pairs", c.node_pairs.size()}});
  const nlohmann::json json = {{"package", fs::absolute(o.output).string()},
                               {"objects", objects},
                               {"materials", scenario.materials.size()},
                               {"connections", connections},
                               {"groups", core::organ_groups(scenario)}};
  if (o.json) {
    print_json(json);
    return;
  }
  std::ostringstream out;
  out << "wrote " << json["package"].get<std::string>() << " (" << scenario.objects.size()
      << " objects, " << scenario.connections.size() << " connections)\n";
  for (const auto& object : objects)
    out << "  " << object["id"].get<std::string>() << ": " << object["triangles"] << " triangles, "
        << object["body"].get<std::string>() << " body of " << object["body_tets"] << " tets\n";
  for (const auto& c : connections)
    out << "  " << c["id"].get<std::string>() << ": " << c["node_pairs"] << " knot pairs\n";
  print_text(out.str());
}

}  // namespace

void add_model_output_commands(CLI::App& model) {
  auto o = std::make_shared<OutputOptions>();
  auto* mesh_command =
      model.add_subcommand("mesh", "Tessellate a model (and build its body) into VTK files");
  mesh_command->add_option("model", o->models, "Model JSON")->required()->expected(1);
  mesh_command->add_option("-o,--output", o->output, "Surface .vtp")->required();
  mesh_command->add_option("--body", o->body, "Also write the simulation body .vtu");
  mesh_command->add_flag("--json", o->json, "Print JSON");
  mesh_command->callback([o] { mesh(*o); });

  auto* package_command = model.add_subcommand(
      "package", "Build the models' bodies and connections into a scenario package");
  package_command->add_option("models", o->models, "Model JSON files")->required();
  package_command->add_option("-o,--output", o->output, "Output package (.vscene or .vscz)")
      ->required();
  package_command->add_option("--name", o->name, "Scenario name");
  package_command->add_flag("--json", o->json, "Print JSON");
  package_command->callback([o] { package(*o); });
}

}  // namespace viscera::cli
