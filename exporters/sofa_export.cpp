// SOFA: the scene XML (sofa_scene_exporter.h) and, in the folder named after it, each body as a
// legacy VTK file SOFA's MeshVTKLoader reads and each surface as OBJ with its MTL and maps.
#include <set>

#include "exporters/assimp_scene.h"
#include "exporters/format_writers.h"
#include "exporters/sofa_scene_exporter.h"
#include "exporters/staged_output.h"
#include "exporters/vtk_legacy_writer.h"

namespace viscera::exporters {

void write_sofa(const core::Scenario& scenario, const std::vector<ExportObject>& objects,
                const std::filesystem::path& main, const std::string& shown) {
  const std::string folder = main.stem().string() + "_meshes";
  // The scene first: it refuses objects SOFA cannot simulate before any file is written.
  const std::string scene = sofa_scene_xml(scenario, objects, folder);
  const std::filesystem::path directory = main.parent_path() / folder;
  std::filesystem::create_directories(directory);
  for (const auto& object : objects) {
    if (object.has_body())
      write_legacy_vtk_tets(object.source->body, false, directory / (object.id() + "_body.vtk"),
                            shown);
    const std::string stem = object.id() + "_surface";
    const AssimpExportScene assimp = make_assimp_scene({object}, TextureStorage::SideFiles, stem);
    export_assimp_scene(*assimp.scene, "obj", directory / (stem + ".obj"), shown);
    std::set<std::string> written;
    for (const auto& [name, bytes] : assimp.side_files) {
      if (written.insert(name).second) write_bytes(bytes, directory / name, shown);
    }
  }
  write_bytes(scene, main, shown);
}

}  // namespace viscera::exporters
