// Wavefront OBJ through assimp: groups per object, normals and UVs in the .obj; the .mtl names
// the maps written beside it (map_Kd albedo, bump/norm normal map, map_Ks specular).
#include <set>

#include "exporters/assimp_scene.h"
#include "exporters/format_writers.h"
#include "exporters/staged_output.h"

namespace viscera::exporters {

void write_obj(const std::vector<ExportObject>& objects, const std::filesystem::path& main,
               const std::string& shown) {
  const AssimpExportScene scene =
      make_assimp_scene(objects, TextureStorage::SideFiles, main.stem().string());
  export_assimp_scene(*scene.scene, "obj", main, shown);
  std::set<std::string> written;
  for (const auto& [name, bytes] : scene.side_files) {
    if (written.insert(name).second) write_bytes(bytes, main.parent_path() / name, shown);
  }
}

}  // namespace viscera::exporters
