#pragma once
/// The contents of a gmsh .msh file in gmsh's own terms (nodes by tag, element blocks by
/// entity), read by a parser of our own: formats 2.x (2.0–2.2) and 4.1, ASCII and binary, either
/// byte order, and the ASCII 4.0 of gmsh 4.0. Sections other than $MeshFormat, $PhysicalNames,
/// $Entities, $Nodes and $Elements ($NodeData, $Periodic, $Comments, …) are skipped. Reference: the
/// gmsh 4.8 manual, §9.1 "MSH file format" and §9.2 "Legacy formats".

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/math_types.h"

namespace viscera::importers {

/// One block of elements of one type in one geometric entity (v4 writes them so; v2 files are
/// grouped into such blocks by type, elementary and physical tag while reading).
struct GmshElementBlock {
  int type = 0;       ///< gmsh element type: 2 triangle, 3 quadrangle, 4 tetrahedron, 11 …
  int dimension = 0;  ///< 0 point, 1 curve, 2 surface, 3 volume
  int entity = 0;     ///< elementary (geometric entity) tag
  int physical = 0;   ///< first physical tag of the entity, 0 if none
  int nodes_per_element = 0;
  std::vector<std::int64_t> tags;   ///< element tag of each element
  std::vector<std::int64_t> nodes;  ///< node tags, nodes_per_element per element
  std::size_t size() const { return nodes_per_element == 0 ? 0 : nodes.size() / nodes_per_element; }
};

/// Everything a mesh reader takes from a .msh file. Coordinates as written (no unit applied).
struct GmshFile {
  double version = 0.0;  ///< 2.2, 4.1, …
  bool binary = false;
  std::vector<std::int64_t> node_tags;  ///< tag of node i
  std::vector<core::Vec3> nodes;        ///< coordinates of node i
  std::vector<GmshElementBlock> blocks;
  std::map<std::pair<int, int>, std::string> physical_names;  ///< (dimension, tag) → name
};

/// Nodes per element of gmsh element `type` (types 1–31 of the manual), or 0 if unknown.
int gmsh_nodes_per_element(int type);
/// Dimension of gmsh element `type` (0–3), or -1 if unknown.
int gmsh_element_dimension(int type);

/// Reads a .msh file. Throws core::InputError naming the file and the section (and element or
/// node) where it is truncated, malformed, of an unsupported version, or refers to nodes that
/// do not exist.
GmshFile read_gmsh_file(const std::filesystem::path& path);

}  // namespace viscera::importers
