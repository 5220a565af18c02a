#include "core/surfaces/bicubic_surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "core/mesh/surface_mesh.h"

namespace viscera::core {
namespace {

/// A wavy open sheet: z = 0.1 sin(x) cos(y) on an uneven grid.
std::vector<Vec3> wavy_grid(int rows, int cols) {
  std::vector<Vec3> points;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const double x = c + 0.2 * std::sin(r), y = r * 1.3;
      points.emplace_back(x, y, 0.1 * std::sin(x) * std::cos(y));
    }
  return points;
}

/// A tube: rings of `cols` points around z, radius varying along z (seed 002 §3.1 lattice).
std::vector<Vec3> tube_grid(int rows, int cols, double radius, double length) {
  std::vector<Vec3> points;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const double a = 2.0 * std::numbers::pi * c / cols;
      points.emplace_back(radius * std::cos(a), radius * std::sin(a), length * r / (rows - 1));
    }
  return points;
}

TEST(BicubicSurface, interpolates_every_grid_point) {
  const auto points = wavy_grid(5, 6);
  const BicubicSurface surface(points, 5, 6, false, false);
  for (int r = 0; r < 5; ++r)
    for (int c = 0; c < 6; ++c)
      EXPECT_LT((surface.point(c, r) - points[static_cast<std::size_t>(r * 6 + c)]).norm(), 1e-13);
  const BicubicSurface tube(tube_grid(4, 8, 0.01, 0.05), 4, 8, true, false);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 8; ++c)
      EXPECT_LT((tube.point(c, r) - tube.grid()[static_cast<std::size_t>(r * 8 + c)]).norm(),
                1e-15);
}

TEST(BicubicSurface, tangent_planes_are_continuous_across_patch_borders) {
  const BicubicSurface surface(wavy_grid(5, 6), 5, 6, false, false);
  const double eps = 1e-9;
  double worst = 0.0;
  for (int border = 1; border < 5; ++border) {
    for (int k = 0; k <= 20; ++k) {
      const double v = 4.0 * k / 20.0;
      // Across a u-border: derivatives in knot parameters agree on both sides (C1).
      const Vec3 left = surface.derivative_u(border - eps, v),
                 right = surface.derivative_u(border + eps, v);
      worst = std::max(worst, (left - right).norm() / right.norm());
      const double u = 5.0 * k / 20.0;
      const Vec3 below = surface.derivative_v(u, std::min(border, 3) - eps),
                 above = surface.derivative_v(u, std::min(border, 3) + eps);
      worst = std::max(worst, (below - above).norm() / above.norm());
    }
  }
  EXPECT_LT(worst, 1e-6);
}

TEST(BicubicSurface, closed_tube_is_seamless_and_near_its_circle) {
  const BicubicSurface tube(tube_grid(3, 12, 0.01, 0.04), 3, 12, true, false);
  double worst = 0.0;
  for (int k = 0; k <= 120; ++k) {
    const double u = 12.0 * k / 120.0;
    const Vec3 p = tube.point(u, 1.3);
    worst = std::max(worst, std::abs(std::hypot(p.x(), p.y()) - 0.01));
  }
  EXPECT_LT(worst, 0.01 * 2e-3);  // twelve points per ring give the circle to 0.2 %
  EXPECT_LT((tube.point(0.0, 0.5) - tube.point(12.0, 0.5)).norm(), 1e-15);
  EXPECT_LT((tube.derivative_u(1e-9, 0.5) - tube.derivative_u(12.0 - 1e-9, 0.5)).norm(),
            1e-6 * tube.derivative_u(0.0, 0.5).norm());
}

TEST(BicubicSurface, tessellation_has_requested_resolution_uvs_and_outward_normals) {
  const BicubicSurface tube(tube_grid(4, 8, 0.01, 0.05), 4, 8, true, false);
  const SurfaceMesh mesh = tessellate(tube, {5, 3});
  EXPECT_EQ(mesh.vertices.size(), static_cast<std::size_t>((8 * 5) * (3 * 3 + 1)));
  EXPECT_EQ(mesh.triangles.size(), static_cast<std::size_t>(2 * 40 * 9));
  ASSERT_EQ(mesh.uvs.size(), mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    EXPECT_GE(mesh.uvs[i].minCoeff(), 0.0);
    EXPECT_LE(mesh.uvs[i].maxCoeff(), 1.0);
    // u runs counter-clockwise around z and v along z, so S_u × S_v points outward.
    const Vec3 radial(mesh.vertices[i].x(), mesh.vertices[i].y(), 0.0);
    EXPECT_GT(mesh.normals[i].dot(radial.normalized()), 0.99);
  }
  for (const auto& t : mesh.triangles) {
    const Vec3 n = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                       .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    const Vec3 c = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
    EXPECT_GT(n.dot(Vec3(c.x(), c.y(), 0.0)), 0.0);
  }
  // Closed in both directions: a torus from a grid, watertight and consistently oriented.
  std::vector<Vec3> torus;
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 8; ++c) {
      const double a = 2.0 * std::numbers::pi * c / 8, b = 2.0 * std::numbers::pi * r / 6;
      torus.emplace_back((0.05 + 0.01 * std::cos(a)) * std::cos(b),
                         (0.05 + 0.01 * std::cos(a)) * std::sin(b), 0.01 * std::sin(a));
    }
  EXPECT_TRUE(is_closed_and_consistently_oriented(
      tessellate(BicubicSurface(torus, 6, 8, true, true), {4, 4})));
}

TEST(BicubicSurface, rejects_small_or_degenerate_grids) {
  EXPECT_THROW(BicubicSurface(wavy_grid(1, 4), 1, 4, false, false), UsageError);
  EXPECT_THROW(BicubicSurface(wavy_grid(2, 2), 2, 2, true, false), UsageError);
  EXPECT_THROW(BicubicSurface(std::vector<Vec3>(6, Vec3::Zero()), 2, 3, false, false), UsageError);
  EXPECT_THROW(tessellate(BicubicSurface(wavy_grid(2, 3), 2, 3, false, false), {0, 2}), UsageError);
}

}  // namespace
}  // namespace viscera::core
