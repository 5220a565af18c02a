#include "core/primitives/flat_primitive.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core/error.h"
#include "tests/core/primitive_checks.h"

namespace viscera::core {
namespace {

using testing::is_watertight_and_outward;

TEST(FlatPrimitive, planar_slab_is_watertight_with_the_volume_of_its_box) {
  const FlatPrimitive flat =
      make_flat(Vec3(0, 0, 0), Vec3(0.08, 0, 0), Vec3(0, 0.05, 0), 4, 5, 0.004);
  const SurfaceMesh mesh = tessellate_flat(flat);
  EXPECT_TRUE(is_watertight_and_outward(mesh));
  EXPECT_NEAR(enclosed_volume(mesh), 0.08 * 0.05 * 0.004, 1e-12);
  EXPECT_NEAR(surface_area(mesh), 2 * 0.08 * 0.05 + 2 * (0.08 + 0.05) * 0.004, 1e-12);
  const BoundingBox box = bounds(mesh);
  EXPECT_NEAR(box.min.z(), -0.002, 1e-15);
  EXPECT_NEAR(box.max.z(), 0.002, 1e-15);
}

TEST(FlatPrimitive, open_sheet_passes_through_its_control_points_and_has_one_border) {
  FlatPrimitive flat = make_flat(Vec3(0, 0, 0), Vec3(0.06, 0, 0), Vec3(0, 0.06, 0), 4, 4);
  flat.open = true;
  flat.control_points[5].z() = 0.01;  // a bump
  const SurfaceMesh sheet = tessellate_flat(flat);
  const int steps = flat.steps_per_patch, columns = 3 * steps + 1;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      EXPECT_LT((sheet.vertices[static_cast<std::size_t>(r * steps * columns + c * steps)] -
                 flat.control_points[static_cast<std::size_t>(r * 4 + c)])
                    .norm(),
                1e-15);
    }
  // Border edges: the 4 · 3 · steps sample intervals around the sheet, each used once.
  std::map<std::pair<int, int>, int> uses;
  for (const auto& t : sheet.triangles)
    for (int e = 0; e < 3; ++e)
      ++uses[std::minmax(t[e], t[(e + 1) % 3])];
  int border = 0;
  for (const auto& [edge, count] : uses)
    border += count == 1 ? 1 : 0;
  EXPECT_EQ(border, 4 * 3 * steps);
  for (const auto& uv : sheet.uvs)
    EXPECT_TRUE(uv.minCoeff() >= 0.0 && uv.maxCoeff() <= 1.0);
}

TEST(FlatPrimitive, moving_a_control_point_reshapes_smoothly_and_stays_watertight) {
  const FlatPrimitive rest =
      make_flat(Vec3(0, 0, 0), Vec3(0.1, 0, 0), Vec3(0, 0.1, 0), 5, 5, 0.003);
  const SurfaceMesh rest_mesh = tessellate_flat(rest);
  double previous = 0.0;
  for (const double h : {0.005, 0.01, 0.02}) {
    FlatPrimitive flat = rest;
    flat.control_points[12].z() += h;  // the middle point
    const SurfaceMesh mesh = tessellate_flat(flat);
    EXPECT_TRUE(is_watertight_and_outward(mesh));
    double largest = 0.0;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
      largest = std::max(largest, (mesh.vertices[v] - rest_mesh.vertices[v]).norm());
    EXPECT_GE(largest, h - 1e-12);
    EXPECT_LT(largest, 1.3 * h);
    if (previous > 0.0) {
      EXPECT_NEAR(largest / previous, 2.0, 0.15);  // nearly linear in the move
    }
    previous = largest;
  }
  // No crease in the sheet: its largest turn between neighbouring triangles halves when the
  // tessellation is refined twofold, as on a C1 surface.
  FlatPrimitive sheet = rest;
  sheet.open = true;
  sheet.control_points[12].z() += 0.02;
  sheet.control_points[6].y() += 0.01;
  const double coarse = testing::max_dihedral_turn(tessellate_flat(sheet));
  sheet.steps_per_patch *= 2;
  const double fine = testing::max_dihedral_turn(tessellate_flat(sheet));
  EXPECT_LT(fine, 0.6 * coarse);
}

TEST(FlatPrimitive, rejects_inconsistent_grids) {
  FlatPrimitive flat = make_flat(Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), 3, 3);
  flat.cols = 4;
  EXPECT_THROW(tessellate_flat(flat), UsageError);
  EXPECT_THROW(make_flat(Vec3::Zero(), Vec3::UnitX(), Vec3::UnitX(), 3, 3), UsageError);
  EXPECT_THROW(make_flat(Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY(), 3, 3, 0.0), UsageError);
}

}  // namespace
}  // namespace viscera::core
