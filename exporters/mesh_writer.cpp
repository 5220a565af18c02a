#include "exporters/mesh_writer.h"

#include <algorithm>

#include "core/error.h"
#include "core/package/vtk_mesh_io.h"
#include "exporters/export_object.h"
#include "exporters/format_writers.h"
#include "exporters/gmsh_msh_writer.h"
#include "exporters/staged_output.h"
#include "exporters/vtk_legacy_writer.h"

namespace viscera::exporters {
namespace {

void check_extension(const std::filesystem::path& path, const std::vector<std::string>& known,
                     const char* what) {
  if (std::find(known.begin(), known.end(), path.extension().string()) == known.end()) {
    std::string list;
    for (const auto& e : known)
      list += (list.empty() ? "" : " ") + e;
    throw core::UsageError("cannot write " + std::string(what) + " as \"" + path.string() +
                           "\": use " + list);
  }
}

core::SurfaceMesh merged(const std::vector<ExportObject>& objects) {
  if (objects.size() == 1) return objects.front().surface;
  core::SurfaceMesh all;
  for (const auto& object : objects) {
    const auto offset = static_cast<int>(all.vertices.size());
    const auto& s = object.surface;
    all.vertices.insert(all.vertices.end(), s.vertices.begin(), s.vertices.end());
    all.normals.insert(all.normals.end(), s.normals.begin(), s.normals.end());
    for (const auto& t : s.triangles)
      all.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  const bool uvs = std::all_of(objects.begin(), objects.end(),
                               [](const ExportObject& o) { return !o.surface.uvs.empty(); });
  if (uvs) {
    for (const auto& object : objects)
      all.uvs.insert(all.uvs.end(), object.surface.uvs.begin(), object.surface.uvs.end());
  }
  return all;
}

}  // namespace

std::vector<std::string> mesh_writer_extensions() {
  return {".obj", ".stl", ".ply", ".gltf", ".glb", ".vtp", ".vtk", ".msh"};
}

std::vector<std::string> tet_mesh_writer_extensions() {
  return {".vtu", ".vtk", ".msh"};
}

void write_meshes(const std::vector<NamedSurface>& surfaces, const std::filesystem::path& path) {
  const std::string file = path.string();
  check_extension(path, mesh_writer_extensions(), "a surface");
  if (surfaces.empty()) throw core::InputError("nothing to export", {file, "", ""});
  core::Scenario holder;
  for (const auto& s : surfaces) {
    if (s.mesh == nullptr || s.mesh->triangles.empty())
      throw core::InputError("surface has no triangles", {file, "", s.name});
    core::SceneObject object;
    object.id = s.name;
    object.surface = *s.mesh;
    holder.objects.push_back(std::move(object));
  }
  std::size_t sanitized = 0;
  const std::vector<ExportObject> objects = gather_export_objects(holder, {}, {}, sanitized);
  StagedOutput staged(path);
  const std::string extension = path.extension().string();
  const auto main = staged.main_file();
  if (extension == ".obj") write_obj(objects, main, file);
  if (extension == ".stl") write_stl(objects, main, file);
  if (extension == ".ply") write_ply(objects, main, file);
  if (extension == ".gltf" || extension == ".glb")
    write_gltf(objects, extension == ".glb", main, file);
  if (extension == ".vtp") core::write_surface_vtp(merged(objects), {}, main);
  if (extension == ".vtk") write_legacy_vtk_surface(merged(objects), main, file);
  if (extension == ".msh") write_msh(objects, main, file);
  staged.commit();
}

void write_tet_mesh(const core::TetMesh& body, const std::string& name,
                    const std::filesystem::path& path) {
  const std::string file = path.string();
  check_extension(path, tet_mesh_writer_extensions(), "a tetrahedral mesh");
  core::check_tet_mesh(body, name);
  StagedOutput staged(path);
  const std::string extension = path.extension().string();
  const auto main = staged.main_file();
  if (extension == ".vtu") core::write_body_vtu(body, main);
  if (extension == ".vtk") write_legacy_vtk_tets(body, true, main, file);
  if (extension == ".msh") {
    const std::vector<core::Triangle> boundary =
        body.surface_faces.empty() ? core::boundary_faces(body.tets) : body.surface_faces;
    write_gmsh_msh41({{name, &body.nodes, &body.tets,
                       body.tet_labels.empty() ? nullptr : &body.tet_labels, &boundary}},
                     main, file);
  }
  staged.commit();
}

}  // namespace viscera::exporters
