#include "importers/meshing/tet_boundary_surface.h"

#include "core/error.h"

namespace viscera::importers {

TetBoundarySurface tet_boundary_surface(const core::TetMesh& body) {
  if (body.tets.empty() || body.surface_faces.empty())
    throw core::InputError("the body has no tetrahedra or no boundary to take a surface from");
  // One tet and corner per node, the first in tet order: deterministic.
  std::vector<int> tet_of(body.nodes.size(), -1), corner_of(body.nodes.size(), -1);
  for (std::size_t t = 0; t < body.tets.size(); ++t) {
    for (int c = 0; c < 4; ++c) {
      const int node = body.tets[t][static_cast<std::size_t>(c)];
      if (tet_of[static_cast<std::size_t>(node)] < 0) {
        tet_of[static_cast<std::size_t>(node)] = static_cast<int>(t);
        corner_of[static_cast<std::size_t>(node)] = c;
      }
    }
  }
  std::vector<int> vertex_of(body.nodes.size(), -1);
  TetBoundarySurface out;
  out.mesh.triangles.reserve(body.surface_faces.size());
  for (const auto& face : body.surface_faces) {
    core::Triangle triangle{};
    for (std::size_t c = 0; c < 3; ++c) {
      const auto node = static_cast<std::size_t>(face[c]);
      if (vertex_of[node] < 0) {
        vertex_of[node] = static_cast<int>(out.mesh.vertices.size());
        out.mesh.vertices.push_back(body.nodes[node]);
        out.embedding.tet.push_back(tet_of[node]);
        std::array<double, 4> weights{0.0, 0.0, 0.0, 0.0};
        weights[static_cast<std::size_t>(corner_of[node])] = 1.0;
        out.embedding.weights.push_back(weights);
      }
      triangle[c] = vertex_of[node];
    }
    out.mesh.triangles.push_back(triangle);
  }
  core::compute_vertex_normals(out.mesh);
  return out;
}

}  // namespace viscera::importers
