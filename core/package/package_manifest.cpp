#include "core/package/package_manifest.h"

#include <functional>
#include <map>
#include <set>

#include "core/error.h"
#include "core/json_numbers.h"
#include "core/json_schema/json_schema_validator.h"
#include "core/json_text.h"
#include "core/package/package_schema.h"

namespace viscera::core {
namespace {

/// Forward migrations: entry n turns a version-n manifest into version n+1. Version 1 is the
/// first, so there is none yet; the loop below is where version 2 plugs in.
const std::map<int, std::function<void(nlohmann::json&)>>& migrations() {
  static const std::map<int, std::function<void(nlohmann::json&)>> table;
  return table;
}

/// The member `key` of `j`, or an empty object or array when it is absent. Returning a
/// reference (not a copy) keeps range-for over .items() valid.
const nlohmann::json& member_or_empty_object(const nlohmann::json& j, const char* key) {
  static const nlohmann::json empty = nlohmann::json::object();
  const auto it = j.find(key);
  return it != j.end() ? *it : empty;
}
const nlohmann::json& member_or_empty_array(const nlohmann::json& j, const char* key) {
  static const nlohmann::json empty = nlohmann::json::array();
  const auto it = j.find(key);
  return it != j.end() ? *it : empty;
}

PackageIssue manifest_issue(const std::string& pointer, const std::string& message) {
  return {kManifestFile, pointer, message};
}

}  // namespace

nlohmann::json parse_manifest(const std::string& text, const std::string& file) {
  return parse_json_text(text, file);
}

void check_format_and_migrate(nlohmann::json& manifest, const std::string& file) {
  if (!manifest.is_object()) throw InputError("manifest must be a JSON object", {file, "", ""});
  const auto format = manifest.find("format");
  if (format == manifest.end() || *format != kPackageFormat) {
    throw InputError(
        std::string("not a Viscera scenario package (format must be \"") + kPackageFormat + "\")",
        {file, "/format", ""});
  }
  const auto version = manifest.find("version");
  if (version == manifest.end() || !whole_number_fits<int>(*version) || version->get<int>() < 1) {
    throw InputError("version must be a whole number from 1", {file, "/version", ""});
  }
  int v = version->get<int>();
  if (v > kPackageVersion) {
    throw UnsupportedVersionError("package version " + std::to_string(v) +
                                      " is newer than this Viscera reads (" +
                                      std::to_string(kPackageVersion) + "); update Viscera",
                                  {file, "/version", ""});
  }
  for (; v < kPackageVersion; ++v) {
    migrations().at(v)(manifest);
    manifest["version"] = v + 1;
  }
}

std::vector<PackageIssue> check_manifest_schema(const nlohmann::json& manifest) {
  static const JsonSchemaValidator validator(package_manifest_schema());
  std::vector<PackageIssue> issues;
  for (const auto& violation : validator.validate(manifest)) {
    issues.push_back(manifest_issue(violation.pointer, violation.message));
  }
  return issues;
}

std::vector<PackageIssue> check_manifest_references(const nlohmann::json& manifest) {
  std::vector<PackageIssue> issues;
  const auto& scenario = manifest.at("scenario");
  const auto& files = manifest.at("files");
  const auto check_file = [&](const nlohmann::json& path, const std::string& pointer) {
    if (!files.contains(path.get<std::string>())) {
      issues.push_back(manifest_issue(
          pointer, "file \"" + path.get<std::string>() + "\" is not listed in /files"));
    }
  };
  const auto keyed_ids = [&](const char* member) {
    std::set<std::string> ids;
    for (const auto& [key, value] : member_or_empty_object(scenario, member).items()) {
      ids.insert(key);
      if (value.at("id") != key) {
        issues.push_back(manifest_issue(
            "/scenario/" + std::string(member) + "/" + escape_pointer_token(key) + "/id",
            "id \"" + value.at("id").get<std::string>() + "\" differs from its key \"" + key +
                "\""));
      }
    }
    return ids;
  };
  const std::set<std::string> materials = keyed_ids("materials");
  const std::set<std::string> textures = keyed_ids("textures");

  std::set<std::string> objects;
  const auto& object_list = scenario.at("objects");
  for (std::size_t i = 0; i < object_list.size(); ++i) {
    const auto& o = object_list[i];
    const std::string pointer = "/scenario/objects/" + std::to_string(i);
    const std::string id = o.at("id").get<std::string>();
    if (!objects.insert(id).second)
      issues.push_back(manifest_issue(pointer + "/id", "object id \"" + id + "\" is used twice"));
    const std::string material = o.value("material", std::string());
    if (!material.empty() && !materials.contains(material)) {
      issues.push_back(
          manifest_issue(pointer + "/material", "unknown material id \"" + material + "\""));
    }
    const std::string texture = o.value("texture", std::string());
    if (!texture.empty() && !textures.contains(texture)) {
      issues.push_back(
          manifest_issue(pointer + "/texture", "unknown texture id \"" + texture + "\""));
    }
    check_file(o.at("surface"), pointer + "/surface");
    if (o.at("body_kind") != "none") {
      if (!o.contains("body")) {
        issues.push_back(manifest_issue(
            pointer, "object with body_kind " + o.at("body_kind").dump() + " names no body file"));
      } else {
        check_file(o.at("body"), pointer + "/body");
      }
    }
    if (o.contains("hydrometra")) check_file(o.at("hydrometra"), pointer + "/hydrometra");
  }
  for (const auto& [key, texture] : member_or_empty_object(scenario, "textures").items()) {
    for (const auto& [map, path] : member_or_empty_object(texture, "maps").items()) {
      check_file(path, "/scenario/textures/" + escape_pointer_token(key) + "/maps/" +
                           escape_pointer_token(map));
    }
  }

  const auto check_object = [&](const char* list, const char* member, bool required) {
    const auto& entries = member_or_empty_array(scenario, list);
    for (std::size_t i = 0; i < entries.size(); ++i) {
      const std::string value = entries[i].value(member, std::string());
      if (value.empty() && !required) continue;
      if (!objects.contains(value)) {
        issues.push_back(manifest_issue(
            "/scenario/" + std::string(list) + "/" + std::to_string(i) + "/" + member,
            "unknown object id \"" + value + "\""));
      }
    }
  };
  check_object("vessel_trees", "host_object", false);
  check_object("pathologies", "host_object", false);
  check_object("pathologies", "object", false);
  check_object("connections", "object_a", true);
  check_object("connections", "object_b", true);
  check_object("active_deformations", "target_object", false);

  std::set<std::string> trees;
  for (const auto& tree : member_or_empty_array(scenario, "vessel_trees"))
    trees.insert(tree.at("id").get<std::string>());
  const auto& deformations = member_or_empty_array(scenario, "active_deformations");
  for (std::size_t i = 0; i < deformations.size(); ++i) {
    const auto& d = deformations[i];
    const std::string base = "/scenario/active_deformations/" + std::to_string(i);
    if (d.at("type") == "pulse") {
      const std::string tree =
          member_or_empty_object(d, "pulse").value("vessel_tree", std::string());
      if (!tree.empty() && !trees.contains(tree)) {
        issues.push_back(
            manifest_issue(base + "/pulse/vessel_tree", "unknown vessel tree id \"" + tree + "\""));
      }
    }
    if (!d.contains(d.at("type").get<std::string>())) {
      issues.push_back(manifest_issue(base, "active deformation of type " + d.at("type").dump() +
                                                " has no \"" + d.at("type").get<std::string>() +
                                                "\" member"));
    }
  }
  return issues;
}

}  // namespace viscera::core
