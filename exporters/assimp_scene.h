#pragma once
/// The assimp scene that assimp's exporters (glTF 2.0, OBJ, STL, PLY) write: one node, mesh and
/// material per object. Internal to exporters/.

#include <assimp/scene.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "exporters/export_object.h"

namespace viscera::exporters {

/// Where the baked maps go.
enum class TextureStorage {
  Embedded,   ///< in the scene (aiScene::mTextures, "*k" references): glTF data URIs, GLB buffer
  SideFiles,  ///< as PNG files beside the main file, referenced by name: OBJ's MTL
  None,       ///< not at all: STL, PLY
};

/// A scene and the side files its materials reference (file name → PNG bytes).
struct AssimpExportScene {
  std::unique_ptr<aiScene> scene;
  std::vector<std::pair<std::string, std::string>> side_files;
};

/// Builds the scene: positions (m), normals, the first UV set with 2 components, vertex colours
/// from the albedo attributes, and a material per object with the base colour (white under a
/// texture, a tissue tone otherwise), no metalness, roughness 0.5 (moist tissue), and the
/// albedo as diffuse and base-colour texture, the normal map as normal texture and the specular
/// map as specular texture. Side files are named "<stem>_<texture id>_<map>.png".
AssimpExportScene make_assimp_scene(const std::vector<ExportObject>& objects,
                                    TextureStorage storage, const std::string& stem);

/// Runs assimp's exporter `format_id` ("gltf2", "glb2", "obj", "stlb", "plyb") on `scene` into
/// `path`; throws core::OutputError naming `shown` with assimp's reason.
void export_assimp_scene(const aiScene& scene, const std::string& format_id,
                         const std::filesystem::path& path, const std::string& shown);

}  // namespace viscera::exporters
