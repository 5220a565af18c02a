// PLY through assimp: positions, normals, UVs (s, t) and vertex colours of every object in one
// vertex and face list. Binary little-endian, except when an object has vertex colours: assimp
// 5.2.5's binary PLY writer declares colours as uchar but writes floats, so such files are
// written as ASCII PLY, which it gets right.
#include <algorithm>

#include "exporters/assimp_scene.h"
#include "exporters/format_writers.h"

namespace viscera::exporters {

void write_ply(const std::vector<ExportObject>& objects, const std::filesystem::path& main,
               const std::string& shown) {
  const AssimpExportScene scene =
      make_assimp_scene(objects, TextureStorage::None, main.stem().string());
  const bool colours = std::any_of(objects.begin(), objects.end(),
                                   [](const ExportObject& o) { return o.has_vertex_colors(); });
  export_assimp_scene(*scene.scene, colours ? "ply" : "plyb", main, shown);
}

}  // namespace viscera::exporters
