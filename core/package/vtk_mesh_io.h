#pragma once
/// Visual surfaces and simulation bodies as VTK XML files (DESIGN.md §4), so that any user can
/// open a package's meshes in ParaView.
///
// clang-format off
/// | file        | VTK type            | arrays                                                   |
/// |-------------|---------------------|----------------------------------------------------------|
/// | surface.vtp | vtkPolyData         | points (float64), triangles; point data "Normals" (3), "UV" (2), "embedding_tet" (int64), "embedding_weights" (4), and one float64 array per vertex attribute |
/// | body.vtu    | vtkUnstructuredGrid | points (float64), VTK_TETRA cells; point data "node_mass" (kg), "fixed" (uint8); cell data "tet_label" (int32); field data "surface_faces" (int64, 3 per face) |
// clang-format on
///
/// Files are written uncompressed in appended raw binary: the same mesh gives the same bytes.

#include <filesystem>

#include "core/mesh/surface_embedding.h"
#include "core/mesh/surface_mesh.h"
#include "core/mesh/tet_mesh.h"

class vtkPolyData;
class vtkUnstructuredGrid;

namespace viscera::core {

/// Converts a surface (and its embedding, if any) to polydata with the arrays above.
void surface_to_polydata(const SurfaceMesh& surface, const SurfaceEmbedding& embedding,
                         vtkPolyData& polydata);
/// Reads a surface and embedding back; polygons that are not triangles raise InputError
/// naming `what`.
void polydata_to_surface(vtkPolyData& polydata, const std::string& what, SurfaceMesh& surface,
                         SurfaceEmbedding& embedding);

/// Converts a tet mesh to an unstructured grid with the arrays above.
void tet_mesh_to_grid(const TetMesh& body, vtkUnstructuredGrid& grid);
/// Reads a tet mesh back; cells that are not tetrahedra raise InputError naming `what`.
TetMesh grid_to_tet_mesh(vtkUnstructuredGrid& grid, const std::string& what);

/// Writes surface.vtp; throws OutputError naming the file.
void write_surface_vtp(const SurfaceMesh& surface, const SurfaceEmbedding& embedding,
                       const std::filesystem::path& path);
/// Reads surface.vtp and checks it; throws InputError naming the file.
void read_surface_vtp(const std::filesystem::path& path, SurfaceMesh& surface,
                      SurfaceEmbedding& embedding);

/// Writes body.vtu; throws OutputError naming the file.
void write_body_vtu(const TetMesh& body, const std::filesystem::path& path);
/// Reads body.vtu and checks it; throws InputError naming the file.
TetMesh read_body_vtu(const std::filesystem::path& path);

}  // namespace viscera::core
