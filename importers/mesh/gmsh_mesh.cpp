#include "importers/mesh/gmsh_mesh.h"

#include <algorithm>
#include <unordered_map>

#include "core/error.h"
#include "importers/mesh/mesh_integrity.h"
#include "importers/mesh/no_tetrahedra_error.h"

namespace viscera::importers {
namespace {

bool is_triangle(int type) {
  return type == 2 || type == 9 || (type >= 20 && type <= 25);
}
bool is_quadrangle(int type) {
  return type == 3 || type == 10 || type == 16;
}
bool is_tetrahedron(int type) {
  return type == 4 || type == 11 || (type >= 29 && type <= 31);
}

/// Node tags → indices of the nodes that elements use, numbered in file order.
class UsedNodes {
 public:
  UsedNodes(const GmshFile& content, const std::string& file) : content_(content), file_(file) {
    slot_.reserve(content.node_tags.size());
    for (std::size_t i = 0; i < content.node_tags.size(); ++i) {
      if (!slot_.emplace(content.node_tags[i], i).second) {
        throw core::InputError(
            "node tag " + std::to_string(content.node_tags[i]) + " is defined twice",
            {file, "", ""});
      }
    }
    index_.assign(content.node_tags.size(), -1);
  }

  /// Marks the node of `tag` as used; returns its position in the file's node list.
  std::size_t use(std::int64_t tag, const GmshElementBlock& block) {
    const auto found = slot_.find(tag);
    if (found == slot_.end()) {
      throw core::InputError("an element of entity " + std::to_string(block.entity) +
                                 " refers to node " + std::to_string(tag) +
                                 ", which $Nodes does not define",
                             {file_, "", ""});
    }
    index_[found->second] = 0;
    return found->second;
  }

  /// Numbers the used nodes in file order and returns their coordinates.
  std::vector<core::Vec3> number() {
    std::vector<core::Vec3> nodes;
    for (std::size_t i = 0; i < index_.size(); ++i) {
      if (index_[i] < 0) continue;
      index_[i] = static_cast<int>(nodes.size());
      nodes.push_back(content_.nodes[i]);
    }
    return nodes;
  }
  int index(std::size_t slot) const { return index_[slot]; }

 private:
  const GmshFile& content_;
  const std::string& file_;
  std::unordered_map<std::int64_t, std::size_t> slot_;
  std::vector<int> index_;
};

}  // namespace

core::SurfaceMesh gmsh_surface(const GmshFile& content, const std::string& file) {
  UsedNodes used(content, file);
  std::vector<std::pair<std::int64_t, std::array<std::size_t, 3>>> faces;  // (element tag, face)
  for (const auto& block : content.blocks) {
    const bool triangle = is_triangle(block.type), quadrangle = is_quadrangle(block.type);
    if (!triangle && !quadrangle) continue;
    for (std::size_t e = 0; e < block.size(); ++e) {
      const std::int64_t* n =
          block.nodes.data() + e * static_cast<std::size_t>(block.nodes_per_element);
      const std::int64_t tag = block.tags[e];
      if (triangle) {
        faces.push_back(
            {tag, {used.use(n[0], block), used.use(n[1], block), used.use(n[2], block)}});
      } else {
        const std::size_t a = used.use(n[0], block), b = used.use(n[1], block),
                          c = used.use(n[2], block), d = used.use(n[3], block);
        faces.push_back({tag, {a, b, c}});
        faces.push_back({tag, {a, c, d}});
      }
    }
  }
  if (faces.empty()) {
    const bool has_tets = std::any_of(
        content.blocks.begin(), content.blocks.end(),
        [](const GmshElementBlock& b) { return is_tetrahedron(b.type) && b.size() > 0; });
    if (!has_tets)
      throw core::InputError("the file holds neither triangles nor tetrahedra", {file, "", ""});
    // A volume mesh alone: its surface is the boundary of its tetrahedra.
    const core::TetMesh body = gmsh_tet_mesh(content, file);
    core::SurfaceMesh surface;
    surface.vertices = body.nodes;
    surface.triangles = body.surface_faces;
    return surface;
  }
  // Elements in tag order, as they were numbered, whichever entity block holds them.
  std::stable_sort(faces.begin(), faces.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  core::SurfaceMesh surface;
  surface.vertices = used.number();
  surface.triangles.reserve(faces.size());
  for (const auto& [tag, f] : faces)
    surface.triangles.push_back({used.index(f[0]), used.index(f[1]), used.index(f[2])});
  return surface;
}

core::TetMesh gmsh_tet_mesh(const GmshFile& content, const std::string& file) {
  UsedNodes used(content, file);
  struct Tet {
    std::int64_t tag;
    std::array<std::size_t, 4> corners;
    int label;
  };
  std::vector<Tet> tets;
  for (const auto& block : content.blocks) {
    if (block.dimension != 3) continue;
    if (!is_tetrahedron(block.type)) {
      throw core::InputError(
          "entity " + std::to_string(block.entity) + " holds " + std::to_string(block.size()) +
              " volume elements of gmsh type " + std::to_string(block.type) +
              " (hexahedra, prisms or pyramids); only tetrahedral meshes are read",
          {file, "", ""});
    }
    const int label = block.physical != 0 ? block.physical : block.entity;
    for (std::size_t e = 0; e < block.size(); ++e) {
      const std::int64_t* n =
          block.nodes.data() + e * static_cast<std::size_t>(block.nodes_per_element);
      tets.push_back({block.tags[e],
                      {used.use(n[0], block), used.use(n[1], block), used.use(n[2], block),
                       used.use(n[3], block)},
                      label});
    }
  }
  // Elements in tag order, as they were numbered, whichever entity block holds them.
  std::stable_sort(tets.begin(), tets.end(),
                   [](const Tet& a, const Tet& b) { return a.tag < b.tag; });
  if (tets.empty()) throw NoTetrahedraError("the file holds no tetrahedra", {file, "", ""});
  core::TetMesh mesh;
  mesh.nodes = used.number();
  mesh.tets.reserve(tets.size());
  mesh.tet_labels.reserve(tets.size());
  for (const auto& [tag, t, label] : tets) {
    mesh.tets.push_back({used.index(t[0]), used.index(t[1]), used.index(t[2]), used.index(t[3])});
    mesh.tet_labels.push_back(label);
  }
  core::orient_tets_positively(mesh);
  core::check_tet_mesh(mesh, file);
  mesh.surface_faces = checked_boundary_faces(mesh, file);
  return mesh;
}

}  // namespace viscera::importers
