#include "core/primitives/ball_primitive.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "tests/core/primitive_checks.h"

namespace viscera::core {
namespace {

using testing::is_watertight_and_outward;

TEST(BallPrimitive, volume_and_area_converge_to_the_sphere) {
  const double r = 0.03;
  const double sphere_volume = 4.0 / 3.0 * std::numbers::pi * r * r * r,
               sphere_area = 4.0 * std::numbers::pi * r * r;
  double previous_volume_error = 1.0, previous_area_error = 1.0;
  for (int s = 1; s <= 6; ++s) {
    BallPrimitive ball = make_ball(Vec3(0.01, -0.02, 0.1), r, 1, s);
    const SurfaceMesh mesh = tessellate_ball(ball);
    EXPECT_TRUE(is_watertight_and_outward(mesh)) << s;
    const double volume_error = std::abs(enclosed_volume(mesh) / sphere_volume - 1.0);
    const double area_error = std::abs(surface_area(mesh) / sphere_area - 1.0);
    // Second-order convergence: each 4-to-1 split divides the error by about four.
    EXPECT_LT(volume_error, 0.3 * previous_volume_error) << s;
    EXPECT_LT(area_error, 0.3 * previous_area_error) << s;
    previous_volume_error = volume_error;
    previous_area_error = area_error;
  }
  EXPECT_LT(previous_volume_error, 1e-3);
  EXPECT_LT(previous_area_error, 1e-3);
}

TEST(BallPrimitive, moved_control_point_is_interpolated_and_others_stay) {
  BallPrimitive ball = make_ball(Vec3::Zero(), 0.03, 0, 5);
  const auto directions = ball_control_directions(0);
  ball.control_points[3] += Vec3(0.01, 0.004, -0.003);
  const BallShape shape(ball);
  for (std::size_t k = 0; k < directions.size(); ++k) {
    EXPECT_LT((shape.point(directions[k]) - ball.control_points[k]).norm(), 1e-12) << k;
  }
  const SurfaceMesh mesh = tessellate_ball(ball);
  EXPECT_TRUE(is_watertight_and_outward(mesh));
  // Star-shaped about the centre still: every triangle faces away from it.
  for (const auto& t : mesh.triangles) {
    const Vec3 n = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                       .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    EXPECT_GT(n.dot(mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]), 0.0);
  }
}

TEST(BallPrimitive, reshapes_smoothly_and_in_proportion_to_the_move) {
  const BallPrimitive rest = make_ball(Vec3::Zero(), 0.03, 1, 5);
  const SurfaceMesh rest_mesh = tessellate_ball(rest);
  const Vec3 move(0.004, 0.006, 0.002);
  double previous = 0.0;
  for (const double fraction : {0.25, 0.5, 1.0}) {
    BallPrimitive ball = rest;
    ball.control_points[7] += fraction * move;
    const SurfaceMesh mesh = tessellate_ball(ball);
    double largest = 0.0;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
      largest = std::max(largest, (mesh.vertices[v] - rest_mesh.vertices[v]).norm());
    // The field is linear in the displacements: half the move, half the change; and no
    // vertex moves much further than the control point did.
    EXPECT_GE(largest, fraction * move.norm() - 1e-12);
    EXPECT_LT(largest, 1.5 * fraction * move.norm());
    if (previous > 0.0) {
      EXPECT_NEAR(largest / previous, 2.0, 1e-9);
    }
    previous = largest;
  }
  // Smooth, no crease: the largest turn between neighbouring triangles halves with each
  // refinement, as it does on a C1 surface (a crease would keep it constant).
  BallPrimitive moved = rest;
  moved.control_points[7] += 2.0 * move;
  moved.subdivisions = 5;
  const double coarse = testing::max_dihedral_turn(tessellate_ball(moved));
  moved.subdivisions = 6;
  const double fine = testing::max_dihedral_turn(tessellate_ball(moved));
  EXPECT_LT(fine, 0.6 * coarse);
}

TEST(BallPrimitive, reproduces_a_moved_and_scaled_control_set_exactly) {
  BallPrimitive ball = make_ball(Vec3::Zero(), 0.02, 1, 3);
  for (auto& p : ball.control_points)
    p = Vec3(0.1, 0.0, 0.05) + 1.5 * p;
  const BallShape shape(ball);
  for (const Vec3& d :
       {Vec3(1, 0, 0), Vec3(0.3, -0.2, 0.9), Vec3(-1, -1, -1), Vec3(0.01, 0.7, -0.2)}) {
    EXPECT_LT((shape.point(d) - (Vec3(0.1, 0.0, 0.05) + 0.03 * d.normalized())).norm(), 1e-12);
  }
}

TEST(BallPrimitive, rejects_wrong_control_counts_and_radii) {
  BallPrimitive ball = make_ball(Vec3::Zero(), 0.02);
  ball.control_points.pop_back();
  EXPECT_THROW(tessellate_ball(ball), UsageError);
  EXPECT_THROW(make_ball(Vec3::Zero(), -1.0), UsageError);
  EXPECT_THROW(make_ball(Vec3::Zero(), 1.0, 3), UsageError);
}

}  // namespace
}  // namespace viscera::core
