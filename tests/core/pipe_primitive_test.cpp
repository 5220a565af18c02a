#include "core/primitives/pipe_primitive.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "tests/core/primitive_checks.h"

namespace viscera::core {
namespace {

using testing::is_watertight_and_outward;

PipePrimitive straight(double r, double length, int ring_segments = 48) {
  PipePrimitive pipe;
  pipe.points = {{0, 0, 0}, {0.3 * length, 0, 0}, {length, 0, 0}};
  pipe.radii = {r, r, r};
  pipe.ring_segments = ring_segments;
  return pipe;
}

TEST(PipePrimitive, straight_pipe_volume_is_within_one_percent_of_pi_r2_l) {
  const double r = 0.004, length = 0.1;
  const SurfaceMesh mesh = tessellate_pipe(straight(r, length));
  EXPECT_TRUE(is_watertight_and_outward(mesh));
  const double volume = enclosed_volume(mesh), expected = std::numbers::pi * r * r * length;
  EXPECT_LT(std::abs(volume / expected - 1.0), 0.01) << volume << " vs " << expected;
  const BoundingBox box = bounds(mesh);
  EXPECT_NEAR(box.min.x(), 0.0, 1e-12);
  EXPECT_NEAR(box.max.x(), length, 1e-12);
}

TEST(PipePrimitive, round_caps_add_a_sphere_and_a_taper_gives_a_frustum) {
  const double r = 0.004, length = 0.1;
  PipePrimitive pipe = straight(r, length);
  pipe.start_cap = pipe.end_cap = PipeCap::Round;
  const SurfaceMesh capsule = tessellate_pipe(pipe);
  EXPECT_TRUE(is_watertight_and_outward(capsule));
  const double capsule_volume =
      std::numbers::pi * r * r * length + 4.0 / 3.0 * std::numbers::pi * r * r * r;
  EXPECT_LT(std::abs(enclosed_volume(capsule) / capsule_volume - 1.0), 0.01);

  PipePrimitive cone;
  cone.points = {{0, 0, 0}, {0, 0, length}};
  cone.radii = {0.006, 0.002};
  cone.ring_segments = 48;
  const SurfaceMesh frustum = tessellate_pipe(cone);
  EXPECT_TRUE(is_watertight_and_outward(frustum));
  const double frustum_volume =
      std::numbers::pi * length * (0.006 * 0.006 + 0.006 * 0.002 + 0.002 * 0.002) / 3.0;
  EXPECT_LT(std::abs(enclosed_volume(frustum) / frustum_volume - 1.0), 0.01);
}

TEST(PipePrimitive, bent_pipe_volume_follows_pappus) {
  // A quarter torus: centre line on a circle of radius R, tube radius r; Pappus gives
  // V = π r² · (length of the centre line).
  const double big = 0.05, r = 0.005;
  PipePrimitive pipe;
  for (int i = 0; i <= 6; ++i) {
    const double a = 0.5 * std::numbers::pi * i / 6;
    pipe.points.emplace_back(big * std::cos(a), big * std::sin(a), 0.0);
    pipe.radii.push_back(r);
  }
  pipe.ring_segments = 48;
  const SurfaceMesh mesh = tessellate_pipe(pipe);
  EXPECT_TRUE(is_watertight_and_outward(mesh));
  const double expected = std::numbers::pi * r * r * 0.5 * std::numbers::pi * big;
  EXPECT_LT(std::abs(enclosed_volume(mesh) / expected - 1.0), 0.015);
}

TEST(PipePrimitive, moving_a_centre_point_moves_the_tube_through_it) {
  PipePrimitive pipe = straight(0.004, 0.1);
  pipe.points[1] = Vec3(0.03, 0.02, 0.01);
  const SurfaceMesh mesh = tessellate_pipe(pipe);
  EXPECT_TRUE(is_watertight_and_outward(mesh));
  // The ring through the moved point: vertices at the radius from it.
  int on_ring = 0;
  for (const auto& v : mesh.vertices)
    on_ring += std::abs((v - pipe.points[1]).norm() - 0.004) < 2e-4 ? 1 : 0;
  EXPECT_GE(on_ring, pipe.ring_segments / 2);
  // The tube wall (caps left open) has no crease: refining both directions twofold halves
  // its largest turn between neighbouring triangles.
  pipe.start_cap = pipe.end_cap = PipeCap::Open;
  const double coarse = testing::max_dihedral_turn(tessellate_pipe(pipe));
  pipe.ring_segments *= 2;
  const double fine = testing::max_dihedral_turn(tessellate_pipe(pipe));
  EXPECT_LT(fine, 0.6 * coarse);
}

TEST(PipePrimitive, open_ends_leave_two_borders_and_bad_input_is_refused) {
  PipePrimitive pipe = straight(0.004, 0.1, 16);
  pipe.start_cap = pipe.end_cap = PipeCap::Open;
  const SurfaceMesh tube = tessellate_pipe(pipe);
  EXPECT_FALSE(is_closed_and_consistently_oriented(tube));
  EXPECT_EQ(tube.vertices.size() % 16, 0u);
  pipe.radii.pop_back();
  EXPECT_THROW(tessellate_pipe(pipe), UsageError);
  EXPECT_THROW(pipe_cap_from_string("square"), UsageError);
}

}  // namespace
}  // namespace viscera::core
