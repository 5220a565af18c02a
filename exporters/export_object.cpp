#include "exporters/export_object.h"

#include <algorithm>

#include "core/error.h"
#include "exporters/surface_sanitizer.h"

namespace viscera::exporters {

std::vector<ExportObject> gather_export_objects(const core::Scenario& scenario,
                                                const TextureFiles& textures,
                                                const ExportOptions& options,
                                                std::size_t& sanitized) {
  for (const auto& id : options.objects) {
    if (scenario.find_object(id) == nullptr)
      throw core::UsageError("the scenario has no object \"" + id + "\"");
  }
  std::vector<ExportObject> objects;
  for (const auto& object : scenario.objects) {
    const bool chosen = options.objects.empty() ||
                        std::find(options.objects.begin(), options.objects.end(), object.id) !=
                            options.objects.end();
    if (!chosen || object.surface.triangles.empty()) continue;
    ExportObject out;
    out.source = &object;
    out.surface = object.surface;
    sanitized += sanitize_surface(out.surface, "object " + object.id + " surface");
    if (const auto material = scenario.materials.find(object.material);
        material != scenario.materials.end()) {
      out.material = &material->second;
    }
    if (const auto texture = scenario.textures.find(object.texture);
        texture != scenario.textures.end()) {
      out.texture_id = texture->first;
      for (const auto& [map, path] : texture->second.maps) {
        const auto bytes = textures.find(path);
        if (bytes == textures.end()) {
          throw core::InputError(
              "texture map \"" + path + "\" of texture \"" + texture->first + "\" is missing",
              {"", "", "object " + object.id});
        }
        out.maps[map] = bytes->second;
      }
      // A map is only usable with UVs; vertex-coloured objects keep their colours instead.
      if (out.surface.uvs.empty()) out.maps.clear();
    }
    objects.push_back(std::move(out));
  }
  if (objects.empty())
    throw core::UsageError("nothing to export: no selected object has a surface");
  return objects;
}

}  // namespace viscera::exporters
