#pragma once
/// manifest.json of a scenario package: parsing, format and version checks with forward
/// migration, schema validation and the references between the scenario's parts.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/package/scenario_package.h"

namespace viscera::core {

/// File name of the manifest inside a package.
inline constexpr const char* kManifestFile = "manifest.json";

/// Parses manifest text; throws InputError naming `file` and the byte of a syntax error.
nlohmann::json parse_manifest(const std::string& text, const std::string& file);

/// Checks the format name and version and migrates older versions forward in place.
/// Throws InputError for a wrong format or a malformed version and UnsupportedVersionError
/// for a version newer than kPackageVersion.
void check_format_and_migrate(nlohmann::json& manifest, const std::string& file);

/// Schema violations (docs/scenario-package.schema.json) as issues of manifest.json.
std::vector<PackageIssue> check_manifest_schema(const nlohmann::json& manifest);

/// References between the parts of a schema-valid manifest: unique ids, materials, textures,
/// host objects, vessel trees and the files each object and texture map names.
std::vector<PackageIssue> check_manifest_references(const nlohmann::json& manifest);

}  // namespace viscera::core
