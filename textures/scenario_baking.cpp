#include "textures/scenario_baking.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/error.h"
#include "textures/png_io.h"
#include "textures/solid_texture.h"
#include "textures/surface_projector.h"
#include "textures/texture_baker.h"
#include "textures/texture_preset.h"
#include "textures/texture_synthesis.h"
#include "textures/triplanar_texture.h"

namespace viscera::textures {

std::string texture_map_path(const std::string& texture_id, const std::string& map) {
  return "textures/" + texture_id + "_" + map + ".png";
}

void apply_uv_atlas(core::SceneObject& object, const UvAtlas& atlas) {
  core::SurfaceEmbedding embedding;
  if (!object.embedding.empty()) {
    for (const int v : atlas.original_vertex) {
      embedding.tet.push_back(object.embedding.tet.at(v));
      embedding.weights.push_back(object.embedding.weights.at(v));
    }
  }
  object.surface = atlas.mesh;
  object.embedding = std::move(embedding);
  // Consumers that need the closed surface's adjacency (surface walks, cutting) weld copies by
  // this index. A surface cut before already carries it, copied per vertex by the atlas, so it
  // keeps pointing at the first uncut surface.
  auto& weld = object.surface.vertex_attributes[kSeamVertexAttribute];
  if (weld.empty()) {
    for (const int v : atlas.original_vertex)
      weld.push_back(static_cast<double>(v));
  }
}

core::SurfaceMesh welded_surface(const core::SurfaceMesh& surface) {
  const auto found = surface.vertex_attributes.find(kSeamVertexAttribute);
  if (found == surface.vertex_attributes.end()) return surface;
  const std::vector<double>& original = found->second;
  const std::size_t n = surface.vertices.size();
  if (original.size() != n) {
    throw core::InputError("the seam_vertex attribute has " + std::to_string(original.size()) +
                           " values for " + std::to_string(n) + " vertices");
  }
  std::vector<int> target(n);
  int count = 0;
  for (std::size_t v = 0; v < n; ++v) {
    const double index = original[v];
    if (!(index >= 0.0) || index >= static_cast<double>(n) || index != std::floor(index)) {
      throw core::InputError("seam_vertex of vertex " + std::to_string(v) + " is " +
                             std::to_string(index) + ", not a vertex of the uncut surface");
    }
    target[v] = static_cast<int>(index);
    count = std::max(count, target[v] + 1);
  }
  core::SurfaceMesh welded;
  welded.vertices.assign(static_cast<std::size_t>(count), core::Vec3::Zero());
  if (!surface.normals.empty())
    welded.normals.assign(static_cast<std::size_t>(count), core::Vec3::Zero());
  for (const auto& [name, values] : surface.vertex_attributes) {
    if (name != kSeamVertexAttribute)
      welded.vertex_attributes[name].assign(static_cast<std::size_t>(count), 0.0);
  }
  for (std::size_t v = 0; v < n; ++v) {
    const auto t = static_cast<std::size_t>(target[v]);
    welded.vertices[t] = surface.vertices[v];
    if (!surface.normals.empty()) welded.normals[t] = surface.normals[v];
    for (const auto& [name, values] : surface.vertex_attributes) {
      if (name != kSeamVertexAttribute) welded.vertex_attributes[name][t] = values[v];
    }
  }
  welded.triangles.reserve(surface.triangles.size());
  for (const auto& tri : surface.triangles)
    welded.triangles.push_back({target[static_cast<std::size_t>(tri[0])],
                                target[static_cast<std::size_t>(tri[1])],
                                target[static_cast<std::size_t>(tri[2])]});
  return welded;
}

BakedTextures bake_textures_into(core::Scenario& scenario, const ScenarioBakeOptions& options,
                                 core::Progress& progress) {
  BakedTextures baked;
  std::set<std::string> used;
  int textured = 0;
  for (const auto& object : scenario.objects)
    textured += !object.texture.empty();
  progress.begin_stage("baking textures", textured);
  for (std::size_t o = 0; o < scenario.objects.size(); ++o) {
    core::SceneObject& object = scenario.objects[o];
    if (object.texture.empty()) continue;
    const std::string pointer = "/scenario/objects/" + std::to_string(o) + "/texture";
    const auto found = scenario.textures.find(object.texture);
    if (found == scenario.textures.end()) {
      throw core::ValidationError("unknown texture id \"" + object.texture + "\"",
                                  {"", pointer, object.id});
    }
    core::TextureSpec spec = found->second;
    if (used.contains(spec.id)) {
      // Each object has its own layout, so a shared spec is baked once per object.
      spec.id = spec.id + "-" + object.id;
      object.texture = spec.id;
    }
    used.insert(spec.id);
    const TexturePreset* preset = nullptr;
    try {
      preset = &find_texture_preset(spec.preset);
    } catch (const core::UsageError& e) {
      throw core::ValidationError(
          e.reason(), {"", "/scenario/textures/" + found->first + "/preset", object.id});
    }
    if (object.surface.triangles.empty()) {
      throw core::ValidationError("a textured object needs a visual surface",
                                  {"", pointer, object.id});
    }

    ObjectBake record{object.id, spec.id, TextureMapping::OwnUvs, 0, {}};
    if (!has_usable_uvs(object.surface)) {
      if (options.keep_topology) {
        record.mapping = TextureMapping::VertexColors;
      } else {
        const UvAtlas atlas = build_uv_atlas(object.surface, {spec.width, options.gutter});
        apply_uv_atlas(object, atlas);
        record.mapping = TextureMapping::Atlas;
        record.charts = atlas.chart_count;
      }
    }
    if (object.surface.normals.size() != object.surface.vertices.size())
      core::compute_vertex_normals(object.surface);

    const SurfaceProjector projector(object.surface);
    const SolidTissueTexture solid(
        *preset, spec.seed, options.texture_scale, options.sample,
        grow_surface_vessels(*preset, projector, options.texture_scale, spec.seed));
    TextureMaps maps;
    if (record.mapping == TextureMapping::VertexColors) {
      bake_vertex_colors(object.surface, solid);
      TextureOptions flat;
      flat.seed = spec.seed;
      flat.width = spec.width;
      flat.height = spec.height;
      flat.sample = options.sample;
      flat.threads = options.threads;
      maps = synthesize_texture(*preset, flat);
    } else {
      record.distortion = measure_uv_distortion(object.surface);
      maps = bake_surface_texture(object.surface, solid,
                                  {spec.width, spec.height, options.gutter, options.threads});
    }
    spec.maps.clear();
    const std::pair<const char*, const Image8*> files[] = {
        {"albedo", &maps.albedo}, {"normal", &maps.normal}, {"specular", &maps.specular}};
    for (const auto& [name, image] : files) {
      const std::string path = texture_map_path(spec.id, name);
      baked.files[path] = encode_png(*image);
      spec.maps[name] = path;
    }
    scenario.textures[spec.id] = spec;
    baked.objects.push_back(record);
    progress.step();
  }
  return baked;
}

}  // namespace viscera::textures
