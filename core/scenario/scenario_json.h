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

/// Conversions of a material (with its measured curve), also used by model documents and
/// material files. from_json throws nlohmann::json exceptions on a wrong type.
void to_json(nlohmann::json& j, const Material& material);
void from_json(const nlohmann::json& j, Material& material);

/// The scenario without meshes (objects have empty surfaces and bodies). Throws
/// ValidationError naming `file` and the JSON pointer (under `pointer_prefix`) when a member
/// has the wrong type or an unknown enumeration value.
/// Conversions of the procedure parts (seed 000 §11), for procedure definitions shipped as data
/// (core/scenario/procedure.h). from_json throws nlohmann::json exceptions on a wrong type.
void to_json(nlohmann::json& j, const TaskSpec& task);
void from_json(const nlohmann::json& j, TaskSpec& task);
void to_json(nlohmann::json& j, const StepSpec& step);
void from_json(const nlohmann::json& j, StepSpec& step);
void to_json(nlohmann::json& j, const InstrumentSpec& instrument);
void from_json(const nlohmann::json& j, InstrumentSpec& instrument);

Scenario scenario_from_json(const nlohmann::json& json, const std::string& file,
                            const std::string& pointer_prefix = "/scenario");

}  // namespace viscera::core
