#include "core/materials/material_file.h"

#include "core/error.h"
#include "core/json_numbers.h"
#include "core/json_text.h"
#include "core/scenario/scenario_json.h"

namespace viscera::core {

nlohmann::json material_file_json(const Material& material, const nlohmann::json& report) {
  return {{"format", kMaterialFormat},
          {"version", kMaterialFormatVersion},
          {"material", material},
          {"report", report}};
}

Material material_from_file_json(const nlohmann::json& json, const std::string& file) {
  if (!has_format(json, kMaterialFormat))
    throw InputError(
        std::string("not a Viscera material (format is not \"") + kMaterialFormat + "\")",
        {file, "/format", ""});
  const auto version = json.find("version");
  if (version == json.end() || !whole_number_fits<int>(*version))
    throw InputError("missing or mistyped version", {file, "/version", ""});
  if (version->get<int>() > kMaterialFormatVersion)
    throw UnsupportedVersionError(
        "material format version " + version->dump() + " is newer than this build reads",
        {file, "/version", ""});
  try {
    return json.at("material").get<Material>();
  } catch (const nlohmann::json::exception& e) {
    throw InputError(std::string("missing or mistyped member: ") + e.what(),
                     {file, "/material", ""});
  }
}

}  // namespace viscera::core
