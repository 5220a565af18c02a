// Binary STL through assimp: every object's triangles in one solid (STL has no names, normals
// per vertex, or textures).
#include "exporters/assimp_scene.h"
#include "exporters/format_writers.h"

namespace viscera::exporters {

void write_stl(const std::vector<ExportObject>& objects, const std::filesystem::path& main,
               const std::string& shown) {
  const AssimpExportScene scene =
      make_assimp_scene(objects, TextureStorage::None, main.stem().string());
  export_assimp_scene(*scene.scene, "stlb", main, shown);
}

}  // namespace viscera::exporters
