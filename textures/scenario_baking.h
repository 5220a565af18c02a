#pragma once
/// Baking a scenario's procedural textures onto its organs (seed 000 §7; DESIGN.md §4): every
/// textured object gets albedo, normal and specular maps in its own UV layout, and the package
/// stores them as textures/<id>_{albedo,normal,specular}.png, listed in TextureSpec::maps.

#include <map>
#include <string>
#include <vector>

#include "core/progress.h"
#include "core/scenario/scenario.h"
#include "textures/image8.h"
#include "textures/uv_atlas.h"

namespace viscera::textures {

/// How baking treats the scenario's surfaces.
struct ScenarioBakeOptions {
  double texture_scale = 0.05;  ///< m of surface per texture width of the preset
  const Image8* sample =
      nullptr;                 ///< user sample image for every texture, or the presets' palettes
  int gutter = 4;              ///< texels around every chart
  bool keep_topology = false;  ///< never split seam vertices (see bake_textures_into)
  int threads = 0;
};

/// How one object's texture was mapped.
enum class TextureMapping {
  OwnUvs,        ///< the surface's UVs were usable and kept
  Atlas,         ///< a new LSCM atlas with automatic seams replaced them
  VertexColors,  ///< keep_topology and no usable UVs: solid texture baked into vertex colours,
                 ///< flat maps stored for triplanar projection at run time
};

/// What happened to one object.
struct ObjectBake {
  std::string object;
  std::string texture;
  TextureMapping mapping = TextureMapping::OwnUvs;
  int charts = 0;
  UvDistortion distortion;  ///< of the UVs the maps were baked in (zeros for vertex colours)
};

/// Files to add to the package (package path → PNG bytes) and the per-object record.
struct BakedTextures {
  std::map<std::string, std::string> files;
  std::vector<ObjectBake> objects;
};

/// Package path of a texture's map: "textures/<id>_<map>.png", map ∈ albedo, normal, specular.
std::string texture_map_path(const std::string& texture_id, const std::string& map);

/// Bakes every object whose `texture` names a TextureSpec: its preset as a solid texture (with
/// vessels grown on that surface), seeded by the spec, at the spec's width × height. An object
/// without usable UVs gets an atlas (apply_uv_atlas), unless keep_topology, in which case it
/// gets vertex colours and the spec's flat maps. A spec shared by several objects is copied per
/// object (id "<texture>-<object>") because each object has its own layout. Sets every baked
/// spec's `maps`. Throws core::ValidationError with the JSON pointer of an unknown texture or
/// preset; CancelledError through `progress`.
BakedTextures bake_textures_into(core::Scenario& scenario, const ScenarioBakeOptions& options,
                                 core::Progress& progress = core::Progress::none());

/// Vertex attribute holding, for every vertex of a surface cut along seams, the index of the
/// vertex it copies in the uncut surface (as a double, like every vertex attribute).
inline constexpr const char* kSeamVertexAttribute = "seam_vertex";

/// Replaces an object's visual surface by the atlas's, whose seam vertices are copies: each copy
/// follows the same tet with the same weights as its original, so the split surface moves as one,
/// and records the original index in the kSeamVertexAttribute attribute.
void apply_uv_atlas(core::SceneObject& object, const UvAtlas& atlas);

/// The closed surface an atlas cut at its seams: every copy is merged back into the vertex its
/// kSeamVertexAttribute names, triangles are re-indexed, texture coordinates dropped and the
/// other vertex attributes and normals taken from one copy of each vertex. A surface without
/// the attribute is returned as it is. Throws core::InputError when the attribute has the wrong
/// length or names a vertex beyond the surface's vertex count.
core::SurfaceMesh welded_surface(const core::SurfaceMesh& surface);

}  // namespace viscera::textures
