#pragma once
/// A material on its own as a JSON file (format "viscera-material", version 1), as written by
/// `viscera material fit` and kept in the asset library:
///   {"format": "viscera-material", "version": 1, "material": {…Material…}, "report": {…}}
/// "report" is free JSON describing how the material was made (the fit's errors, the derived
/// moduli); readers ignore it.

#include <nlohmann/json.hpp>
#include <string>

#include "core/scenario/material.h"

namespace viscera::core {

inline constexpr const char* kMaterialFormat = "viscera-material";
inline constexpr int kMaterialFormatVersion = 1;

/// The document of `material` with `report` (may be null).
nlohmann::json material_file_json(const Material& material, const nlohmann::json& report);

/// The material of a document. Throws InputError naming `file` and the JSON pointer for a
/// wrong format or a missing or mistyped member, UnsupportedVersionError for a newer version.
Material material_from_file_json(const nlohmann::json& json, const std::string& file);

}  // namespace viscera::core
