#include "studio/document/asset_payloads.h"

#include <QTemporaryDir>
#include <fstream>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/materials/material_file.h"
#include "core/modelling/model_document.h"
#include "core/modelling/model_scene.h"
#include "core/version.h"
#include "studio/document/primitive_objects.h"
#include "textures/png_io.h"
#include "textures/surface_thumbnail.h"

namespace viscera::studio {
namespace fs = std::filesystem;
namespace {

fs::path temporary_folder(const QTemporaryDir& dir) {
  if (!dir.isValid()) throw core::OutputError("cannot create a temporary folder", {"", "", ""});
  return fs::path(dir.path().toStdString());
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  if (!in && !in.eof()) throw core::InputError("cannot read the file", {path.string(), "", ""});
  return out.str();
}

/// `base`, `base-2`, … not in `taken`.
std::string free_id(const std::string& base, const std::set<std::string>& taken) {
  if (!taken.contains(base)) return base;
  for (int n = 2;; ++n) {
    const std::string id = base + "-" + std::to_string(n);
    if (!taken.contains(id)) return id;
  }
}

/// Renames the parts of `source` so they fit into `target`; shared materials and textures
/// that are equal are reused.
ModelParts fit_into(DocumentContent source, const core::Scenario& target) {
  ModelParts parts;
  core::Scenario& s = source.scenario;
  std::map<std::string, std::string> material_ids, texture_ids, object_ids;
  std::set<std::string> taken_materials, taken_textures, taken_objects;
  for (const auto& [id, m] : target.materials)
    taken_materials.insert(id);
  for (const auto& [id, t] : target.textures)
    taken_textures.insert(id);
  for (const auto& o : target.objects)
    taken_objects.insert(o.id);
  for (auto& [id, material] : s.materials) {
    const auto existing = target.materials.find(id);
    if (existing != target.materials.end() && existing->second == material) {
      material_ids[id] = id;
      continue;
    }
    material.id = free_id(id, taken_materials);
    taken_materials.insert(material.id);
    material_ids[id] = material.id;
    parts.materials.push_back(material);
  }
  for (auto& [id, texture] : s.textures) {
    const auto existing = target.textures.find(id);
    const std::string new_id = existing != target.textures.end() && existing->second == texture
                                   ? id
                                   : free_id(id, taken_textures);
    texture_ids[id] = new_id;
    if (new_id == id && existing != target.textures.end()) continue;
    taken_textures.insert(new_id);
    texture.id = new_id;
    for (auto& [kind, path] : texture.maps) {
      const auto file = source.files.find(path);
      std::string new_path = path;
      if (new_id != id)
        new_path = "textures/" + new_id + "_" + kind + fs::path(path).extension().string();
      if (file != source.files.end()) parts.files[new_path] = file->second;
      path = new_path;
    }
    parts.textures.push_back(texture);
  }
  for (auto& object : s.objects) {
    const std::string id = free_id(object.id, taken_objects);
    taken_objects.insert(id);
    object_ids[object.id] = id;
    object.id = id;
    if (!object.material.empty() && material_ids.contains(object.material))
      object.material = material_ids[object.material];
    for (auto& [label, material] : object.layer_materials)
      if (material_ids.contains(material)) material = material_ids[material];
    if (!object.texture.empty() && texture_ids.contains(object.texture))
      object.texture = texture_ids[object.texture];
    parts.objects.push_back(std::move(object));
  }
  for (auto& c : s.connections) {
    if (!object_ids.contains(c.object_a) || !object_ids.contains(c.object_b)) continue;
    c.object_a = object_ids[c.object_a];
    c.object_b = object_ids[c.object_b];
    std::set<std::string> taken;
    for (const auto& t : target.connections)
      taken.insert(t.id);
    c.id = free_id(c.id, taken);
    parts.connections.push_back(c);
  }
  return parts;
}

}  // namespace

core::AssetEntry object_asset_entry(const DocumentContent& content, const std::string& object_id,
                                    const std::string& name) {
  const core::SceneObject* object = content.scenario.find_object(object_id);
  if (object == nullptr) throw core::UsageError("the scenario has no object \"" + object_id + "\"");
  DocumentContent part;
  part.scenario.metadata.name = object->name;
  part.scenario.objects.push_back(*object);
  std::set<std::string> materials = {object->material};
  for (const auto& [label, material] : object->layer_materials)
    materials.insert(material);
  for (const auto& id : materials) {
    const auto found = content.scenario.materials.find(id);
    if (found != content.scenario.materials.end()) part.scenario.materials.insert(*found);
  }
  const auto texture = content.scenario.textures.find(object->texture);
  if (texture != content.scenario.textures.end()) {
    part.scenario.textures.insert(*texture);
    for (const auto& [kind, path] : texture->second.maps) {
      const auto file = content.files.find(path);
      if (file != content.files.end()) part.files.insert(*file);
    }
  }
  QTemporaryDir dir;
  const fs::path packed = temporary_folder(dir) / "object.vscz";
  write_document_content(part, packed);

  core::AssetEntry entry;
  entry.summary.name = name;
  entry.summary.type = core::AssetType::Model;
  entry.summary.payload_format = "vscz";
  entry.summary.provenance =
      nlohmann::json{{"object", object_id},
                     {"scenario", content.scenario.metadata.name},
                     {"added_by", "viscera-studio " + core::viscera_version()}}
          .dump();
  entry.payload = read_bytes(packed);
  if (!object->surface.triangles.empty())
    entry.thumbnail =
        textures::encode_png(textures::render_surface_thumbnail(object->surface, 128));
  return entry;
}

core::AssetEntry material_asset_entry(const core::Material& material, const std::string& name) {
  core::AssetEntry entry;
  entry.summary.name = name;
  entry.summary.type = core::AssetType::Material;
  entry.summary.payload_format = "json";
  entry.summary.provenance =
      nlohmann::json{{"material", material.id},
                     {"added_by", "viscera-studio " + core::viscera_version()}}
          .dump();
  entry.payload = core::material_file_json(material, nullptr).dump(2);
  if (material.stress_strain && material.stress_strain->cubic.size() == 4)
    entry.thumbnail = textures::encode_png(
        textures::render_stress_strain_thumbnail(*material.stress_strain, 128));
  return entry;
}

ModelParts model_parts_from_asset(const core::AssetEntry& entry, const core::Scenario& target) {
  const std::string& name = entry.summary.name;
  if (entry.summary.type != core::AssetType::Model)
    throw core::UsageError("library entry " + name + " is a " +
                           core::to_string(entry.summary.type) + ", not a model");
  DocumentContent source;
  if (entry.summary.payload_format == "vscz") {
    QTemporaryDir dir;
    const fs::path packed = temporary_folder(dir) / (name + ".vscz");
    std::ofstream(packed, std::ios::binary) << entry.payload;
    source = read_document_content(packed);
  } else if (entry.summary.payload_format == "json") {
    nlohmann::json json;
    try {
      json = nlohmann::json::parse(entry.payload);
    } catch (const nlohmann::json::parse_error& e) {
      throw core::InputError(std::string("the model is not JSON: ") + e.what(),
                             {"library entry " + name, "", ""});
    }
    source.scenario = core::build_model_scenario({core::model_from_json(json, name)});
  } else {
    throw core::UsageError("library entry " + name + " holds a ." + entry.summary.payload_format +
                           " model; the studio adds .vscz packages and viscera-model documents");
  }
  return fit_into(std::move(source), target);
}

core::Material material_from_asset(const core::AssetEntry& entry) {
  const std::string& name = entry.summary.name;
  if (entry.summary.type != core::AssetType::Material)
    throw core::UsageError("library entry " + name + " is a " +
                           core::to_string(entry.summary.type) + ", not a material");
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(entry.payload);
  } catch (const nlohmann::json::parse_error& e) {
    throw core::InputError(std::string("the material is not JSON: ") + e.what(),
                           {"library entry " + name, "", ""});
  }
  return core::material_from_file_json(json, "library entry " + name);
}

}  // namespace viscera::studio
