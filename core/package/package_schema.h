#pragma once
/// The manifest's JSON Schema, compiled in from docs/scenario-package.schema.json at build time
/// so the product never reads the source tree.

#include <nlohmann/json.hpp>

namespace viscera::core {

/// The parsed schema of manifest.json (docs/scenario-package.schema.json).
const nlohmann::json& package_manifest_schema();

}  // namespace viscera::core
