#pragma once
/// Reading meshes made elsewhere: one entry point for surfaces, one for tetrahedral meshes, both
/// dispatching on the extension to one file per format under importers/mesh/.
///
// clang-format off
/// | extension                       | reader                   | surface: read_mesh()                           | tets: read_tet_mesh()                        |
/// |---------------------------------|--------------------------|------------------------------------------------|----------------------------------------------|
/// | .obj .stl .ply .off .gltf .glb  | assimp                   | triangles (polygons split), normals, UV set 0  | —                                            |
/// | .3ds .dae .fbx, other assimp    | assimp                   | same                                           | —                                            |
/// | .msh: gmsh 2.x and 4.1 (ASCII or binary, either byte order), ASCII 4.0 | own parser (mesh/gmsh_file.h) | triangles and quadrangles, else the tets' boundary | tets (corners of 2nd-order ones), label = physical tag |
/// | .vtp                            | VTK XML PolyData         | polygons and strips split, normals, TCoords/"UV" | —                                          |
/// | .vtu                            | VTK XML UnstructuredGrid | outer surface of the cells, normals, TCoords   | tets, "tet_label", "node_mass", "fixed"      |
/// | .vtk (legacy 4.2 or 5.1)        | VTK legacy reader        | as .vtp or .vtu, by the dataset it holds       | as .vtu                                      |
// clang-format on
///
/// Files state no unit, so the caller says which one they are in; results are in metres. Every
/// surface is checked before it is returned (mesh/mesh_integrity.h): finite, no degenerate
/// triangles, manifold, free of self-intersections. A failure throws core::InputError whose
/// message names the file and the reason; nothing is returned half-read.

#include <filesystem>
#include <string>
#include <vector>

#include "core/mesh/surface_mesh.h"
#include "core/mesh/tet_mesh.h"
#include "importers/mesh/no_tetrahedra_error.h"

namespace viscera::importers {

/// Length units a mesh file may be written in.
enum class LengthUnit { Metre, Centimetre, Millimetre };

/// Metres per unit.
double metres_per(LengthUnit unit);
/// "m", "cm", "mm" → unit; throws core::UsageError otherwise.
LengthUnit length_unit_from_string(const std::string& name);

/// Extensions read_tet_mesh() reads: ".msh", ".vtu", ".vtk".
const std::vector<std::string>& tet_mesh_extensions();
/// True when `path`'s extension (any case) is one of tet_mesh_extensions().
bool may_hold_tetrahedra(const std::filesystem::path& path);

/// Reads the surface of the file in metres (coincident vertices of assimp formats joined). Throws
/// core::InputError naming the file and the reason when it cannot be read, holds no triangles,
/// has non-finite coordinates, degenerate triangles, non-manifold edges or vertices, or
/// intersects itself.
core::SurfaceMesh read_mesh(const std::filesystem::path& path, LengthUnit unit = LengthUnit::Metre);

/// Reads the tetrahedra of a .msh, .vtu or .vtk file in metres: positively oriented, with their
/// outward boundary faces and labels; masses and fixed flags when the file carries them (a
/// package's body.vtu). Throws core::UsageError for other extensions and core::InputError naming
/// the file and the reason when it cannot be read, holds no tetrahedra (NoTetrahedraError), holds
/// other volume elements, non-finite or degenerate ones, or a face shared by three tetrahedra.
core::TetMesh read_tet_mesh(const std::filesystem::path& path, LengthUnit unit = LengthUnit::Metre);

}  // namespace viscera::importers
