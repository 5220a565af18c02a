#include "importers/mesh_reader.h"

#include <algorithm>

#include "importers/mesh/assimp_mesh_file.h"
#include "importers/mesh/gmsh_file.h"
#include "importers/mesh/gmsh_mesh.h"
#include "importers/mesh/mesh_integrity.h"
#include "importers/mesh/vtk_mesh_file.h"

namespace viscera::importers {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return extension;
}

bool is_vtk(const std::string& extension) {
  return extension == ".vtp" || extension == ".vtu" || extension == ".vtk";
}

void scale(std::vector<core::Vec3>& points, double factor) {
  if (factor == 1.0) return;
  for (auto& p : points)
    p *= factor;
}

}  // namespace

double metres_per(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::Metre:
      return 1.0;
    case LengthUnit::Centimetre:
      return 0.01;
    case LengthUnit::Millimetre:
      return 0.001;
  }
  return 1.0;
}

LengthUnit length_unit_from_string(const std::string& name) {
  if (name == "m") return LengthUnit::Metre;
  if (name == "cm") return LengthUnit::Centimetre;
  if (name == "mm") return LengthUnit::Millimetre;
  throw core::UsageError("unknown length unit \"" + name + "\"; use m, cm or mm");
}

const std::vector<std::string>& tet_mesh_extensions() {
  static const std::vector<std::string> extensions = {".msh", ".vtu", ".vtk"};
  return extensions;
}

bool may_hold_tetrahedra(const std::filesystem::path& path) {
  const auto& extensions = tet_mesh_extensions();
  return std::find(extensions.begin(), extensions.end(), lower_extension(path)) != extensions.end();
}

core::SurfaceMesh read_mesh(const std::filesystem::path& path, LengthUnit unit) {
  const std::string extension = lower_extension(path);
  core::SurfaceMesh mesh;
  if (extension == ".msh") {
    mesh = gmsh_surface(read_gmsh_file(path), path.string());
  } else if (is_vtk(extension)) {
    mesh = read_vtk_surface(path);
  } else {
    mesh = read_assimp_surface(path);
  }
  check_surface_integrity(mesh, path.string());
  scale(mesh.vertices, metres_per(unit));
  return mesh;
}

core::TetMesh read_tet_mesh(const std::filesystem::path& path, LengthUnit unit) {
  const std::string extension = lower_extension(path);
  if (!may_hold_tetrahedra(path)) {
    throw core::UsageError("\"" + path.string() +
                           "\" cannot hold a tetrahedral mesh; use .msh, .vtu or .vtk");
  }
  core::TetMesh mesh = extension == ".msh" ? gmsh_tet_mesh(read_gmsh_file(path), path.string())
                                           : read_vtk_tet_mesh(path);
  const double factor = metres_per(unit);
  scale(mesh.nodes, factor);
  // Masses are per node and do not scale with length.
  return mesh;
}

}  // namespace viscera::importers
