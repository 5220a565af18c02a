#pragma once
/// Surface and tetrahedral meshes from the contents of a gmsh file.

#include <string>

#include "core/mesh/surface_mesh.h"
#include "core/mesh/tet_mesh.h"
#include "importers/mesh/gmsh_file.h"

namespace viscera::importers {

/// Triangles (types 2, 9, 20–25: corner nodes) and quadrangles (3, 10, 16: split along their
/// first diagonal) of every entity; if the file has no surface elements, the boundary of its
/// tetrahedra. Only nodes that elements use are kept, in file order. Coordinates as written.
/// Throws core::InputError naming `file` when there is nothing to take or a node is missing.
core::SurfaceMesh gmsh_surface(const GmshFile& content, const std::string& file);

/// Tetrahedra (types 4, 11, 29–31: corner nodes), labelled by their entity's physical tag (its
/// elementary tag if it has none), positively oriented, with their outward boundary. Throws
/// core::InputError naming `file` when there are no tetrahedra, other volume elements
/// (hexahedra, prisms, pyramids), missing nodes, or degenerate tetrahedra.
core::TetMesh gmsh_tet_mesh(const GmshFile& content, const std::string& file);

}  // namespace viscera::importers
