#pragma once
/// Embedding of a visual surface in a simulation body: each surface vertex follows one
/// tetrahedron through barycentric weights, so a fine visual mesh rides on a coarse body.

#include <array>
#include <span>
#include <vector>

#include "core/mesh/tet_mesh.h"

namespace viscera::core {

/// Per visual vertex: the tet it follows and its four barycentric weights (sum 1).
struct SurfaceEmbedding {
  std::vector<int> tet;
  std::vector<std::array<double, 4>> weights;

  bool empty() const { return tet.empty(); }
  bool operator==(const SurfaceEmbedding&) const = default;
};

/// Barycentric coordinates of p in tet (a,b,c,d); they sum to 1 and are all ≥ 0 inside.
std::array<double, 4> barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                                  const Vec3& d);

/// Embeds each point in the tet that contains it, or, for points outside the body (a visual
/// surface slightly outside its tet mesh), in the tet whose smallest barycentric weight is
/// largest among nearby tets. Uses a uniform grid over tet bounding boxes.
/// Throws InputError if the body has no tets.
SurfaceEmbedding embed_points(const std::vector<Vec3>& points, const TetMesh& body);

/// Positions of the embedded points for the body's current node positions.
std::vector<Vec3> embedded_positions(const SurfaceEmbedding& embedding,
                                     const std::vector<Tetrahedron>& tets,
                                     std::span<const Vec3> body_nodes);

}  // namespace viscera::core
