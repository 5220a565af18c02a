#include "studio/cli/library_commands.h"

#include <unistd.h>

#include <filesystem>
#include <sstream>

#include "core/error.h"
#include "core/library/asset_entry_file.h"
#include "core/library/asset_library.h"
#include "core/materials/material_file.h"
#include "core/modelling/model_scene.h"
#include "core/package/scenario_package.h"
#include "core/sha256.h"
#include "core/version.h"
#include "studio/cli/cli_files.h"
#include "studio/cli/command_output.h"
#include "textures/png_io.h"
#include "textures/surface_thumbnail.h"

namespace viscera::cli {
namespace {

namespace fs = std::filesystem;

struct LibraryOptions {
  std::string library;  // --library PATH
  std::string file, name, type, tag, provenance, thumbnail, output, thumbnail_output;
  std::vector<std::string> tags;
  int version = 0;
  bool all_versions = false;
  bool no_thumbnail = false;
  bool json = false;
};

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  if (!ext.empty()) ext.erase(0, 1);
  for (auto& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

/// What a file holds when --type is not given: model and material documents say so in their
/// "format", images are textures, scenario packages templates, meshes models.
core::AssetType infer_type(const fs::path& path, const std::string& ext, const std::string& bytes) {
  if (ext == "json") {
    nlohmann::json json;
    try {
      json = nlohmann::json::parse(bytes);
    } catch (const nlohmann::json::parse_error&) {
      throw core::InputError("not JSON; give --type for other files", {path.string(), "", ""});
    }
    const std::string format = json.is_object() ? json.value("format", std::string()) : "";
    if (format == "viscera-model") return core::AssetType::Model;
    if (format == "viscera-material") return core::AssetType::Material;
    throw core::UsageError("cannot tell the type of " + path.string() +
                           " (no viscera-model or viscera-material format): give --type");
  }
  if (ext == "png" || ext == "jpg" || ext == "jpeg" || ext == "tif" || ext == "tiff")
    return core::AssetType::Texture;
  if (ext == "vscz") return core::AssetType::Template;
  if (ext == "vtp" || ext == "vtu" || ext == "obj" || ext == "stl" || ext == "ply" ||
      ext == "glb" || ext == "gltf" || ext == "msh")
    return core::AssetType::Model;
  throw core::UsageError("cannot tell the type of " + path.string() + ": give --type");
}

nlohmann::json summary_json(const core::AssetSummary& s) {
  return {{"name", s.name},
          {"type", core::to_string(s.type)},
          {"version", s.version},
          {"tags", s.tags},
          {"provenance", s.provenance},
          {"payload_format", s.payload_format},
          {"payload_bytes", s.payload_bytes},
          {"payload_sha256", s.payload_sha256},
          {"thumbnail", s.has_thumbnail}};
}

void add(const LibraryOptions& o) {
  const fs::path path = o.file;
  core::AssetEntry entry;
  core::AssetSummary& s = entry.summary;
  std::string ext = lower_extension(path);
  if (fs::is_directory(path)) {
    // A package folder goes in as its .vscz (checksums verified by pack_package).
    const fs::path packed =
        fs::temp_directory_path() / ("viscera-library-" + std::to_string(::getpid()) + ".vscz");
    core::pack_package(path, packed);
    try {
      entry.payload = read_file_bytes(packed);
    } catch (...) {
      fs::remove(packed);
      throw;
    }
    fs::remove(packed);
    ext = "vscz";
  } else {
    entry.payload = read_file_bytes(path);
  }
  s.type =
      o.type.empty() ? infer_type(path, ext, entry.payload) : core::asset_type_from_string(o.type);
  s.payload_format = ext;
  s.name = o.name;
  if (s.name.empty() && ext == "json") {
    const auto json = nlohmann::json::parse(entry.payload, nullptr, false);
    if (json.is_object() && json.contains("id") && json["id"].is_string()) {
      s.name = json["id"];
    } else if (json.is_object() && json.contains("material") && json["material"].is_object()) {
      s.name = json["material"].value("id", std::string());
    }
  }
  if (s.name.empty()) s.name = path.stem().string();
  s.tags = o.tags;
  s.provenance = o.provenance;
  if (s.provenance.empty()) {
    s.provenance = nlohmann::json{{"file", path.filename().string()},
                                  {"sha256", core::sha256_hex(entry.payload)},
                                  {"added_by", "viscera " + core::viscera_version()}}
                       .dump();
  }
  if (!o.thumbnail.empty()) {
    entry.thumbnail = read_file_bytes(o.thumbnail);
  } else if (!o.no_thumbnail && s.type == core::AssetType::Model && ext == "json") {
    // A model document gets a picture of its tessellation.
    const core::ModelDocument model =
        core::model_from_json(nlohmann::json::parse(entry.payload), path.string());
    entry.thumbnail = textures::encode_png(
        textures::render_surface_thumbnail(core::tessellate_model(model), 128));
  } else if (!o.no_thumbnail && s.type == core::AssetType::Material && ext == "json") {
    // A material with a measured or catalogued curve: a plot of it.
    const core::Material material =
        core::material_from_file_json(nlohmann::json::parse(entry.payload), path.string());
    if (material.stress_strain && material.stress_strain->cubic.size() == 4)
      entry.thumbnail = textures::encode_png(
          textures::render_stress_strain_thumbnail(*material.stress_strain, 128));
  } else if (!o.no_thumbnail && s.type == core::AssetType::Texture) {
    entry.thumbnail = textures::encode_png(
        textures::image_thumbnail(textures::decode_image(entry.payload, path.string()), 128));
  } else if (!o.no_thumbnail && s.type == core::AssetType::Template && ext == "vscz") {
    // A scenario package: all its objects' surfaces in one picture.
    const core::Scenario scenario = core::read_package(path);
    core::SurfaceMesh all;
    for (const auto& object : scenario.objects) {
      const auto offset = static_cast<int>(all.vertices.size());
      all.vertices.insert(all.vertices.end(), object.surface.vertices.begin(),
                          object.surface.vertices.end());
      for (const auto& t : object.surface.triangles)
        all.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    }
    if (!all.triangles.empty())
      entry.thumbnail = textures::encode_png(textures::render_surface_thumbnail(all, 128));
  }
  core::AssetLibrary library(core::resolve_library_path(o.library));
  const core::AssetSummary added = library.add(entry);
  if (o.json) {
    auto json = summary_json(added);
    json["library"] = fs::absolute(library.path()).string();
    print_json(json);
  } else {
    print_text("added " + added.name + " v" + std::to_string(added.version) + " (" +
               core::to_string(added.type) + ", " + human_bytes(added.payload_bytes) + ") to " +
               fs::absolute(library.path()).string() + "\n");
  }
}

void list(const LibraryOptions& o) {
  const core::AssetLibrary library(core::resolve_library_path(o.library));
  std::optional<core::AssetType> type;
  if (!o.type.empty()) type = core::asset_type_from_string(o.type);
  const auto entries = library.list(type, o.tag, o.all_versions);
  if (o.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& s : entries)
      list.push_back(summary_json(s));
    print_json({{"library", fs::absolute(library.path()).string()}, {"entries", list}});
    return;
  }
  std::ostringstream out;
  for (const auto& s : entries) {
    out << s.name << "  v" << s.version << "  " << core::to_string(s.type) << "  "
        << s.payload_format << "  " << human_bytes(s.payload_bytes);
    if (!s.tags.empty()) {
      out << "  [";
      for (std::size_t i = 0; i < s.tags.size(); ++i)
        out << (i ? ", " : "") << s.tags[i];
      out << "]";
    }
    out << (s.has_thumbnail ? "  thumbnail" : "") << "\n";
  }
  print_text(out.str());
}

void get(const LibraryOptions& o) {
  const core::AssetLibrary library(core::resolve_library_path(o.library));
  const core::AssetEntry entry = library.get(o.name, o.version);
  if (!o.thumbnail_output.empty()) {
    if (entry.thumbnail.empty())
      throw core::InputError("the entry has no thumbnail", {library.path().string(), "", o.name});
    textures::write_file_atomically(entry.thumbnail, o.thumbnail_output);
  }
  textures::write_file_atomically(entry.payload, o.output);
  if (o.json) {
    auto json = summary_json(entry.summary);
    json["file"] = fs::absolute(o.output).string();
    print_json(json);
  } else {
    print_text("wrote " + fs::absolute(o.output).string() + " (" + entry.summary.name + " v" +
               std::to_string(entry.summary.version) + ")\n");
  }
}

void remove(const LibraryOptions& o) {
  core::AssetLibrary library(core::resolve_library_path(o.library));
  const int removed = library.remove(o.name, o.version);
  if (o.json) {
    print_json({{"name", o.name}, {"removed_versions", removed}});
  } else {
    print_text("removed " + std::to_string(removed) + " version" + (removed == 1 ? "" : "s") +
               " of " + o.name + "\n");
  }
}

void export_entry(const LibraryOptions& o) {
  const core::AssetLibrary library(core::resolve_library_path(o.library));
  core::export_asset_entry(library.get(o.name, o.version), o.output);
  print_text("wrote " + fs::absolute(o.output).string() + "\n");
}

void import_entry(const LibraryOptions& o) {
  const core::AssetEntry entry = core::import_asset_entry(o.file);
  core::AssetLibrary library(core::resolve_library_path(o.library));
  const core::AssetSummary added = library.add(entry);
  if (o.json) {
    print_json(summary_json(added));
  } else {
    print_text("imported " + added.name + " as v" + std::to_string(added.version) + "\n");
  }
}

}  // namespace

void add_library_commands(CLI::App& app) {
  auto* library = app.add_subcommand(
      "library", "The asset library: models, materials, textures and templates for reuse");
  library->require_subcommand(1);
  library->fallthrough();  // --library may follow the action
  auto o = std::make_shared<LibraryOptions>();
  library->add_option("--library", o->library,
                      "Library database (default: $VISCERA_LIBRARY, else "
                      "$XDG_DATA_HOME/viscera/library.sqlite or "
                      "~/.local/share/viscera/library.sqlite)");

  auto* list_command = library->add_subcommand("list", "List entries (newest versions)");
  list_command->add_option("--type", o->type, "model, material, texture or template");
  list_command->add_option("--tag", o->tag, "Only entries with this tag");
  list_command->add_flag("--all-versions", o->all_versions, "Every version, not only the newest");
  list_command->add_flag("--json", o->json, "Print JSON");
  list_command->callback([o] { list(*o); });

  auto* add_command = library->add_subcommand("add", "Add a file as an entry (next version)");
  add_command->add_option("file", o->file, "Model/material JSON, image, mesh, package")->required();
  add_command->add_option("--name", o->name,
                          "Entry name (default: the id in the file or its stem)");
  add_command->add_option("--type", o->type,
                          "model, material, texture or template (default: from the file)");
  add_command->add_option("--tags", o->tags, "Tags, comma separated")->delimiter(',');
  add_command->add_option("--provenance", o->provenance,
                          "Where it came from (default: file and checksum)");
  add_command->add_option("--thumbnail", o->thumbnail,
                          "PNG thumbnail (default: a rendering of a model or package, a material's "
                          "curve, a scaled texture)");
  add_command->add_flag("--no-thumbnail", o->no_thumbnail, "Store no thumbnail");
  add_command->add_flag("--json", o->json, "Print JSON");
  add_command->callback([o] { add(*o); });

  auto* get_command = library->add_subcommand("get", "Write an entry's payload to a file");
  get_command->add_option("name", o->name, "Entry name")->required();
  get_command->add_option("--version", o->version, "Version (default: newest)");
  get_command->add_option("-o,--output", o->output, "Output file")->required();
  get_command->add_option("--thumbnail", o->thumbnail_output, "Also write the thumbnail PNG here");
  get_command->add_flag("--json", o->json, "Print JSON");
  get_command->callback([o] { get(*o); });

  auto* rm_command = library->add_subcommand("rm", "Remove an entry (all versions or one)");
  rm_command->add_option("name", o->name, "Entry name")->required();
  rm_command->add_option("--version", o->version, "Only this version");
  rm_command->add_flag("--json", o->json, "Print JSON");
  rm_command->callback([o] { remove(*o); });

  auto* export_command =
      library->add_subcommand("export", "Write an entry with its metadata as a .vasset file");
  export_command->add_option("name", o->name, "Entry name")->required();
  export_command->add_option("--version", o->version, "Version (default: newest)");
  export_command->add_option("-o,--output", o->output, "Output .vasset")->required();
  export_command->callback([o] { export_entry(*o); });

  auto* import_command =
      library->add_subcommand("import", "Add an entry from a .vasset file (next version)");
  import_command->add_option("file", o->file, "Input .vasset")->required();
  import_command->add_flag("--json", o->json, "Print JSON");
  import_command->callback([o] { import_entry(*o); });
}

}  // namespace viscera::cli
