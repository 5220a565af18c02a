#pragma once
/// The Scenario as JSON: the "scenario" member of a package manifest (DESIGN.md §4).
/// Meshes are not part of the JSON: each object names its files instead
/// ("surface": "objects/<id>/surface.vtp", "body": "objects/<id>/body.vtu").

#include <nlohmann/json.hpp>
#include <string>

#include "core/scenario/scenario.h"

namespace viscera::core {

/// Package path of an object's visual surface and simulation body.
std::string surface_file_of(const std::string& object_id);
std::string body_file_of(const std::string& object_id);

/// The scenario without meshes. Keys are sorted (nlohmann::json objects), so dumping the
/// result gives the same bytes for the same scenario.
nlohmann::json scenario_to_json(const Scenario& scenario);

/// The scenario without meshes (objects have empty surfaces and bodies). Throws
/// ValidationError naming `file` and the JSON pointer (under `pointer_prefix`) when a member
/// has the wrong type or an unknown enumeration value.
Scenario scenario_from_json(const nlohmann::json& json, const std::string& file,
                            const std::string& pointer_prefix = "/scenario");

}  // namespace viscera::core
