#pragma once
/// Writing meshes as gmsh 4.1 ASCII .msh files (gmsh 4.8 manual §9.1), our own writer: numbers
/// in shortest round-trip form, so a mesh read back is bit-identical and the same mesh gives
/// the same bytes.

#include <filesystem>
#include <string>
#include <vector>

#include "core/math_types.h"

namespace viscera::exporters {

/// One named part: nodes (m) with tetrahedra, triangles, or both (triangles then index the same
/// nodes, e.g. a body's boundary). Pointers stay owned by the caller.
struct MshPart {
  std::string name;
  const std::vector<core::Vec3>* nodes = nullptr;
  const std::vector<core::Tetrahedron>* tets = nullptr;    ///< or nullptr
  const std::vector<int>* tet_labels = nullptr;            ///< per tet, or nullptr
  const std::vector<core::Triangle>* triangles = nullptr;  ///< or nullptr
};

/// Writes the parts: per part and tet label one volume entity with a physical group named after
/// the part ("<name>" or "<name>/label <k>" when the part has several labels), its triangles as
/// one surface entity with physical group "<name>/surface". Volume physical tags are the tet
/// labels when those are positive and distinct across volumes (so they survive a round trip),
/// else 1, 2, …. Node and element tags run from 1 across parts. Throws core::OutputError naming
/// `shown` when the file cannot be written.
void write_gmsh_msh41(const std::vector<MshPart>& parts, const std::filesystem::path& path,
                      const std::string& shown);

}  // namespace viscera::exporters
