#pragma once
/// Surface meshes from every format assimp 5.2 reads (OBJ, STL, PLY, glTF 2.0, OFF, 3DS, COLLADA,
/// FBX, …): all meshes of the scene with node transforms applied, polygons triangulated.

#include <filesystem>

#include "core/mesh/surface_mesh.h"

namespace viscera::importers {

/// Every triangle mesh of the file in one SurfaceMesh, coordinates as written; normals and the
/// first UV set when every part has them (STL's per-facet normals are replaced by smooth ones
/// of the welded mesh). Throws core::InputError naming the file and assimp's reason when it
/// cannot be read or holds no triangles.
core::SurfaceMesh read_assimp_surface(const std::filesystem::path& path);

}  // namespace viscera::importers
