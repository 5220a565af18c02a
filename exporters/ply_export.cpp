// Binary little-endian PLY through assimp: positions, normals, UVs (s, t) and vertex colours of
// every object in one vertex and face list.
#include "exporters/assimp_scene.h"
#include "exporters/format_writers.h"

namespace viscera::exporters {

void write_ply(const std::vector<ExportObject>& objects, const std::filesystem::path& main,
               const std::string& shown) {
  const AssimpExportScene scene =
      make_assimp_scene(objects, TextureStorage::None, main.stem().string());
  export_assimp_scene(*scene.scene, "plyb", main, shown);
}

}  // namespace viscera::exporters
