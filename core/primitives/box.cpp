#include "core/primitives/box.h"

#include <cmath>
#include <map>

#include "core/error.h"

namespace viscera::core {

SurfaceMesh make_box(const Vec3& min, const Vec3& max, double cell) {
  if (!((max - min).array() > 0.0).all())
    throw UsageError("box must have positive extent on every axis");
  if (!(cell > 0.0)) throw UsageError("box cell size must be positive");
  std::array<int, 3> n{};
  for (int a = 0; a < 3; ++a)
    n[a] = std::max(1, static_cast<int>(std::lround((max[a] - min[a]) / cell)));

  SurfaceMesh mesh;
  std::map<std::array<int, 3>, int> vertex_of;  // lattice index → vertex, shared across faces
  const auto vertex = [&](const std::array<int, 3>& lattice) {
    const auto [it, inserted] =
        vertex_of.try_emplace(lattice, static_cast<int>(mesh.vertices.size()));
    if (inserted) {
      Vec3 p;
      for (int a = 0; a < 3; ++a)
        p[a] = min[a] + (max[a] - min[a]) * lattice[a] / n[a];
      mesh.vertices.push_back(p);
    }
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      for (int i = 0; i < n[u]; ++i)
        for (int j = 0; j < n[v]; ++j) {
          std::array<int, 3> corner[4];
          for (int c = 0; c < 4; ++c) {
            corner[c][axis] = side * n[axis];
            corner[c][u] = i + (c == 1 || c == 2);
            corner[c][v] = j + (c >= 2);
          }
          const int q[4] = {vertex(corner[0]), vertex(corner[1]), vertex(corner[2]),
                            vertex(corner[3])};
          // (u, v) turns counter-clockwise about +axis, so the max side keeps this order and
          // the min side reverses it to face outward.
          if (side == 1) {
            mesh.triangles.push_back({q[0], q[1], q[2]});
            mesh.triangles.push_back({q[0], q[2], q[3]});
          } else {
            mesh.triangles.push_back({q[0], q[2], q[1]});
            mesh.triangles.push_back({q[0], q[3], q[2]});
          }
        }
    }
  }
  compute_vertex_normals(mesh);
  return mesh;
}

}  // namespace viscera::core
