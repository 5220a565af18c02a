#include "core/mesh/tet_mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <map>

#include "core/error.h"

namespace viscera::core {

double signed_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

double signed_volume(const TetMesh& mesh, int t) {
  const auto& tet = mesh.tets[t];
  return signed_volume(mesh.nodes[tet[0]], mesh.nodes[tet[1]], mesh.nodes[tet[2]],
                       mesh.nodes[tet[3]]);
}

double total_volume(const TetMesh& mesh) {
  double volume = 0.0;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    volume += signed_volume(mesh, static_cast<int>(t));
  return volume;
}

std::vector<Triangle> boundary_faces(const std::vector<Tetrahedron>& tets) {
  // The faces of a positively oriented tet (a,b,c,d), each counter-clockwise from outside.
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  std::map<std::array<int, 3>, std::pair<int, Triangle>> faces;  // sorted key → (uses, face)
  for (const auto& tet : tets) {
    for (const auto& f : kFaces) {
      const Triangle face{tet[f[0]], tet[f[1]], tet[f[2]]};
      std::array<int, 3> key = face;
      std::sort(key.begin(), key.end());
      auto [it, inserted] = faces.try_emplace(key, 0, face);
      ++it->second.first;
    }
  }
  std::vector<Triangle> boundary;
  for (const auto& [key, entry] : faces) {
    if (entry.first == 1) boundary.push_back(entry.second);
  }
  return boundary;
}

std::vector<double> lumped_node_masses(const TetMesh& mesh, double density) {
  std::vector<double> mass(mesh.nodes.size(), 0.0);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const double quarter = 0.25 * density * std::abs(signed_volume(mesh, static_cast<int>(t)));
    for (const int n : mesh.tets[t])
      mass[n] += quarter;
  }
  return mass;
}

void orient_tets_positively(TetMesh& mesh) {
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    if (signed_volume(mesh, static_cast<int>(t)) < 0.0) std::swap(mesh.tets[t][2], mesh.tets[t][3]);
  }
}

void check_tet_mesh(const TetMesh& mesh, const std::string& what) {
  const auto n = static_cast<int>(mesh.nodes.size());
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
    if (!mesh.nodes[i].allFinite()) {
      throw InputError("node coordinate is not finite", {what, "", "node " + std::to_string(i)});
    }
  }
  // The element's name is only spelled out for the error (a string per tet costs more than
  // the whole check).
  const auto check_index = [&](int v, const char* element, std::size_t index) {
    if (v < 0 || v >= n) {
      throw InputError("refers to node " + std::to_string(v) + " of " + std::to_string(n),
                       {what, "", element + std::to_string(index)});
    }
  };
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    for (const int v : mesh.tets[t])
      check_index(v, "tet ", t);
    if (!(signed_volume(mesh, static_cast<int>(t)) > 0.0)) {
      throw InputError("tetrahedron is degenerate or inverted",
                       {what, "", "tet " + std::to_string(t)});
    }
  }
  for (std::size_t f = 0; f < mesh.surface_faces.size(); ++f) {
    for (const int v : mesh.surface_faces[f])
      check_index(v, "surface face ", f);
  }
  if (!mesh.node_mass.empty() && mesh.node_mass.size() != mesh.nodes.size()) {
    throw InputError("node mass array length differs from node count", {what, "", ""});
  }
  if (!mesh.fixed.empty() && mesh.fixed.size() != mesh.nodes.size()) {
    throw InputError("fixed flag array length differs from node count", {what, "", ""});
  }
  if (!mesh.tet_labels.empty() && mesh.tet_labels.size() != mesh.tets.size()) {
    throw InputError("tet label array length differs from tet count", {what, "", ""});
  }
}

}  // namespace viscera::core
