// gmsh 4.1 of a scenario: every body with its boundary, and the surfaces of objects that have no
// body, one physical group per object (gmsh_msh_writer.h).
#include "core/error.h"
#include "exporters/format_writers.h"
#include "exporters/gmsh_msh_writer.h"

namespace viscera::exporters {

void write_msh(const std::vector<ExportObject>& objects, const std::filesystem::path& main,
               const std::string& shown) {
  std::vector<MshPart> parts;
  std::vector<std::vector<core::Triangle>> boundaries(objects.size());
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const ExportObject& object = objects[i];
    MshPart part;
    part.name = object.id();
    if (object.has_body()) {
      const core::TetMesh& body = object.source->body;
      boundaries[i] =
          body.surface_faces.empty() ? core::boundary_faces(body.tets) : body.surface_faces;
      part.nodes = &body.nodes;
      part.tets = &body.tets;
      part.tet_labels = body.tet_labels.empty() ? nullptr : &body.tet_labels;
      part.triangles = &boundaries[i];
    } else {
      part.nodes = &object.surface.vertices;
      part.triangles = &object.surface.triangles;
    }
    parts.push_back(part);
  }
  write_gmsh_msh41(parts, main, shown);
}

}  // namespace viscera::exporters
