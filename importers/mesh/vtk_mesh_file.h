#pragma once
/// Meshes from VTK files through VTK's own readers: XML PolyData (.vtp), XML UnstructuredGrid
/// (.vtu) and legacy files (.vtk, ASCII or binary, format 4.2 or 5.1, polydata or unstructured
/// grid).

#include <filesystem>

#include "core/mesh/surface_mesh.h"
#include "core/mesh/tet_mesh.h"

namespace viscera::importers {

/// The file's surface: polygons and triangle strips triangulated, or for an unstructured grid
/// its outer surface (vtkDataSetSurfaceFilter); point normals ("Normals" or the active normals)
/// and texture coordinates (the active TCoords, or an array "UV") carried along. Coordinates as
/// written. Throws core::InputError naming the file and VTK's reason when it cannot be read, or
/// when it holds no triangles.
core::SurfaceMesh read_vtk_surface(const std::filesystem::path& path);

/// The file's tetrahedra (VTK_TETRA, and the corners of VTK_QUADRATIC_TETRA), positively
/// oriented, with labels from a cell array "tet_label", "gmsh:physical", "CellEntityIds" or
/// "MaterialIds" when there is one, and the package arrays "node_mass" and "fixed" when present.
/// Cells of lower dimension are ignored. Throws core::InputError naming the file when it cannot
/// be read, holds no tetrahedra, or holds other volume cells.
core::TetMesh read_vtk_tet_mesh(const std::filesystem::path& path);

}  // namespace viscera::importers
