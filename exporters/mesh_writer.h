#pragma once
/// Writing single meshes for other tools (`viscera mesh convert`): one entry point for surfaces
/// and one for tetrahedral meshes, dispatching on the extension to the writers that
/// export_scenario() uses.
///
// clang-format off
/// | extension  | writer               | surfaces: write_meshes()                        | tets: write_tet_mesh()                          |
/// |------------|----------------------|-------------------------------------------------|-------------------------------------------------|
/// | .obj       | assimp               | groups per surface, normals, UVs                | —                                               |
/// | .stl       | assimp               | binary STL, all surfaces in one solid           | —                                               |
/// | .ply       | assimp               | binary PLY (ASCII when coloured): normals, UVs, colours | —                                       |
/// | .gltf .glb | assimp (glTF 2.0)    | a node per surface, unit normals, UVs           | —                                               |
/// | .vtp       | VTK XML              | the surfaces merged: normals, UVs               | —                                               |
/// | .vtk       | VTK legacy 4.2 ASCII | the surfaces merged as POLYDATA                 | UNSTRUCTURED_GRID with node_mass, fixed, tet_label |
/// | .vtu       | VTK XML              | —                                               | the package's body.vtu layout (vtk_mesh_io.h)   |
/// | .msh       | own gmsh 4.1 writer  | a surface entity per surface                    | tets by label, with their boundary triangles    |
// clang-format on
///
/// Positions are written in metres; surfaces are sanitised first (surface_sanitizer.h). The
/// output is written to a temporary sibling and renamed into place, so a failure leaves nothing.

#include <filesystem>
#include <string>
#include <vector>

#include "core/mesh/surface_mesh.h"
#include "core/mesh/tet_mesh.h"

namespace viscera::exporters {

/// A named surface to export.
struct NamedSurface {
  std::string name;
  const core::SurfaceMesh* mesh = nullptr;
};

/// The extensions write_meshes() understands, e.g. ".obj".
std::vector<std::string> mesh_writer_extensions();
/// The extensions write_tet_mesh() understands: ".vtu", ".vtk", ".msh".
std::vector<std::string> tet_mesh_writer_extensions();

/// Writes the surfaces into one file whose format follows the extension. Throws
/// core::UsageError for an unknown extension, core::InputError for an empty or non-finite
/// mesh, and core::OutputError naming the file when writing fails.
void write_meshes(const std::vector<NamedSurface>& surfaces, const std::filesystem::path& path);

/// Writes a tet mesh (named `name` inside formats that name parts). Throws core::UsageError for
/// an unknown extension, core::InputError for a mesh that fails core::check_tet_mesh, and
/// core::OutputError naming the file when writing fails.
void write_tet_mesh(const core::TetMesh& body, const std::string& name,
                    const std::filesystem::path& path);

}  // namespace viscera::exporters
