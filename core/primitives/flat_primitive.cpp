#include "core/primitives/flat_primitive.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace viscera::core {

FlatPrimitive make_flat(const Vec3& origin, const Vec3& u_edge, const Vec3& v_edge, int rows,
                        int cols, double thickness) {
  if (rows < 2 || cols < 2) throw UsageError("a flat needs at least 2 × 2 control points");
  if (!(u_edge.cross(v_edge).norm() > 0.0))
    throw UsageError("the edges of a flat must not be parallel");
  FlatPrimitive flat;
  flat.rows = rows;
  flat.cols = cols;
  flat.thickness = thickness;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      flat.control_points.push_back(origin + u_edge * (static_cast<double>(c) / (cols - 1)) +
                                    v_edge * (static_cast<double>(r) / (rows - 1)));
    }
  check_flat(flat, "flat");
  return flat;
}

void check_flat(const FlatPrimitive& flat, const std::string& what) {
  if (flat.rows < 2 || flat.cols < 2)
    throw UsageError(what + ": a flat needs at least 2 × 2 control points");
  if (flat.control_points.size() !=
      static_cast<std::size_t>(flat.rows) * static_cast<std::size_t>(flat.cols)) {
    throw UsageError(what + ": a " + std::to_string(flat.rows) + " × " + std::to_string(flat.cols) +
                     " flat needs " + std::to_string(flat.rows * flat.cols) +
                     " control points, not " + std::to_string(flat.control_points.size()));
  }
  if (!flat.open && !(flat.thickness > 0.0))
    throw UsageError(what + ": a closed flat needs a positive thickness");
  if (flat.steps_per_patch < 1 || flat.steps_per_patch > 64)
    throw UsageError(what + ": steps per patch must be in [1, 64]");
}

BicubicSurface flat_surface(const FlatPrimitive& flat) {
  check_flat(flat, "flat");
  return BicubicSurface(flat.control_points, flat.rows, flat.cols, false, false,
                        KnotSpacing::ChordLength);
}

SurfaceMesh tessellate_flat(const FlatPrimitive& flat) {
  const BicubicSurface surface = flat_surface(flat);
  const SurfaceTessellation steps{flat.steps_per_patch, flat.steps_per_patch};
  if (flat.open) return tessellate(surface, steps);

  const SurfaceSamples samples = sample_surface(surface, steps);
  const auto n = static_cast<int>(samples.positions.size());
  const double half = 0.5 * flat.thickness;
  SurfaceMesh mesh;
  mesh.vertices.reserve(2 * static_cast<std::size_t>(n));
  // Top layer (vertices 0 … n−1) along +normal, bottom layer (n … 2n−1) along −normal.
  for (int i = 0; i < n; ++i)
    mesh.vertices.push_back(samples.positions[static_cast<std::size_t>(i)] +
                            half * samples.normals[static_cast<std::size_t>(i)]);
  for (int i = 0; i < n; ++i)
    mesh.vertices.push_back(samples.positions[static_cast<std::size_t>(i)] -
                            half * samples.normals[static_cast<std::size_t>(i)]);
  mesh.uvs = samples.uvs;
  for (const Vec2& uv : samples.uvs)
    mesh.uvs.emplace_back(1.0 - uv.x(), uv.y());  // seen from below

  const auto grid = sample_grid_triangles(samples.rows, samples.columns, false, false);
  for (const auto& t : grid)
    mesh.triangles.push_back(t);
  for (const auto& t : grid)
    mesh.triangles.push_back({t[0] + n, t[2] + n, t[1] + n});

  // The rim: walk the border with the sheet on the left seen from above (the direction the
  // top triangles use on their border edges) and join each edge a → b to the bottom layer.
  std::vector<int> loop;
  const int rows = samples.rows, cols = samples.columns;
  for (int c = 0; c < cols - 1; ++c)
    loop.push_back(samples.index(0, c));
  for (int r = 0; r < rows - 1; ++r)
    loop.push_back(samples.index(r, cols - 1));
  for (int c = cols - 1; c > 0; --c)
    loop.push_back(samples.index(rows - 1, c));
  for (int r = rows - 1; r > 0; --r)
    loop.push_back(samples.index(r, 0));
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const int a = loop[k], b = loop[(k + 1) % loop.size()];
    mesh.triangles.push_back({a, b + n, b});
    mesh.triangles.push_back({a, a + n, b + n});
  }
  compute_vertex_normals(mesh);
  return mesh;
}

}  // namespace viscera::core
