#pragma once
/// Legacy VTK files (.vtk, format 4.2 ASCII): the oldest and most widely read VTK form, for
/// tools whose readers predate VTK XML and format 5.1 (SOFA's MeshVTKLoader, older ParaView).

#include <filesystem>
#include <string>

#include "core/mesh/surface_mesh.h"
#include "core/mesh/tet_mesh.h"

namespace viscera::exporters {

/// A surface as POLYDATA with its normals and texture coordinates. Throws core::OutputError
/// naming `shown`.
void write_legacy_vtk_surface(const core::SurfaceMesh& surface, const std::filesystem::path& path,
                              const std::string& shown);

/// A tet mesh as UNSTRUCTURED_GRID; with `arrays` also node_mass, fixed and tet_label
/// (vtk_mesh_io.h), without them points and VTK_TETRA cells only. Throws core::OutputError
/// naming `shown`.
void write_legacy_vtk_tets(const core::TetMesh& body, bool arrays,
                           const std::filesystem::path& path, const std::string& shown);

}  // namespace viscera::exporters
