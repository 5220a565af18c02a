#pragma once
/// One scene object as the format writers see it: its sanitised surface, its body, its material
/// and the bytes of its baked maps. Internal to exporters/.

#include <map>
#include <string>
#include <vector>

#include "core/scenario/scenario.h"
#include "exporters/scenario_exporter.h"

namespace viscera::exporters {

struct ExportObject {
  const core::SceneObject* source = nullptr;
  core::SurfaceMesh surface;                 ///< sanitised copy of source->surface
  const core::Material* material = nullptr;  ///< or nullptr when the object names none
  std::string texture_id;                    ///< or empty
  std::map<std::string, std::string> maps;   ///< "albedo" | "normal" | "specular" → PNG bytes

  const std::string& id() const { return source->id; }
  /// True when the object has a tetrahedral or mass-spring body with tets.
  bool has_body() const {
    return source->body_kind != core::BodyKind::None && !source->body.tets.empty();
  }
  bool has_vertex_colors() const { return surface.vertex_attributes.contains("albedo_r"); }
};

/// The objects `options` selects, in scenario order, prepared for writing; adds the replaced
/// values to `sanitized`. Throws core::UsageError for an unknown id or an empty selection and
/// core::InputError for a map that the texture names but `textures` lacks.
std::vector<ExportObject> gather_export_objects(const core::Scenario& scenario,
                                                const TextureFiles& textures,
                                                const ExportOptions& options,
                                                std::size_t& sanitized);

/// The RGB colour a material shows without texture: a flesh tone, the same for every object.
inline constexpr double kTissueBaseColor[3] = {0.80, 0.45, 0.42};

}  // namespace viscera::exporters
