#include "simulator/cutting/cut_surface.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "simulator/cutting/cut_surface_index.h"

namespace viscera::sim::cutting {
namespace {

using core::Vec3;

double area(const CutSurface& s) {
  double a = 0.0;
  for (const auto& t : s.triangles) {
    a += 0.5 *
         (s.vertices[t[1]] - s.vertices[t[0]]).cross(s.vertices[t[2]] - s.vertices[t[0]]).norm();
  }
  return a;
}

TEST(CutSurface, a_straight_loop_sweep_covers_the_wire_length_times_the_path) {
  LoopElectrode loop;
  loop.radius = 0.004;
  loop.segments = 64;
  std::vector<LoopPose> sweep(5);
  for (int k = 0; k < 5; ++k)
    sweep[k].position = Vec3(0, 0, 0.005 * k);
  const CutSurface s = swept_loop_surface(loop, sweep);
  EXPECT_EQ(s.triangles.size(), 2u * 64u * 4u);
  // The chords of a half circle of radius r: 2·n·r·sin(π/(2n)) long, times the 2 cm path.
  const double wire = 2 * 64 * loop.radius * std::sin(M_PI / (2 * 64));
  EXPECT_NEAR(area(s), wire * 0.02, 1e-12);
  EXPECT_NEAR(wire, M_PI * loop.radius, 1e-5);
}

TEST(CutSurface, planar_and_scissor_surfaces_have_their_area) {
  EXPECT_NEAR(area(planar_cut_surface(Vec3(1, 2, 3), Vec3(0, 0, 2), Vec3(1, 1, 0), 0.01, 0.02, 5)),
              4 * 0.01 * 0.02, 1e-15);
  const CutSurface blades =
      scissor_cut_surface(Vec3::Zero(), Vec3(0.02, 0, 0), Vec3(0.02, 0.01, 0), 4);
  EXPECT_NEAR(area(blades), 0.5 * 0.02 * 0.01, 1e-15);
}

TEST(CutSurface, the_index_finds_crossings_with_their_direction_and_nearest_points) {
  const CutSurface plane =
      planar_cut_surface(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), 0.01, 0.01, 4);
  const CutSurfaceIndex index(plane, 0.002);
  const auto up = index.crossing(Vec3(0.001, 0.002, -0.003), Vec3(0.001, 0.002, 0.001));
  ASSERT_TRUE(up);
  EXPECT_NEAR(up->t, 0.75, 1e-12);
  EXPECT_EQ(up->direction, 1);
  // Through a vertex shared by many triangles: one crossing, not six.
  const auto down = index.crossing(Vec3(0, 0, 0.001), Vec3(0, 0, -0.001));
  ASSERT_TRUE(down);
  EXPECT_NEAR(down->t, 0.5, 1e-12);
  EXPECT_EQ(down->direction, -1);
  EXPECT_FALSE(index.crossing(Vec3(0, 0, 0.001), Vec3(0, 0, 0.002)));
  EXPECT_FALSE(index.crossing(Vec3(0.02, 0, -0.001), Vec3(0.02, 0, 0.001)));  // beyond its edge
  const auto near = index.nearest(Vec3(0.003, 0.004, -0.002), 0.01);
  ASSERT_TRUE(near);
  EXPECT_NEAR(near->distance, 0.002, 1e-15);
  EXPECT_NEAR(near->signed_distance, -0.002, 1e-15);
  EXPECT_FALSE(index.nearest(Vec3(0.003, 0.004, -0.002), 0.001));
}

TEST(CutSurface, bad_loops_and_sweeps_are_refused_with_a_clear_sentence) {
  const auto message = [](auto&& call) {
    try {
      call();
    } catch (const core::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  std::vector<LoopPose> sweep(2);
  sweep[1].position = Vec3(0, 0, 0.01);
  LoopElectrode zero;
  zero.radius = 0.0;
  EXPECT_NE(message([&] { swept_loop_surface(zero, sweep); }).find("radius"), std::string::npos);
  LoopElectrode nan_radius;
  nan_radius.radius = std::nan("");
  EXPECT_NE(message([&] { swept_loop_surface(nan_radius, sweep); }).find("radius"),
            std::string::npos);
  const LoopElectrode loop;
  EXPECT_NE(message([&] { swept_loop_surface(loop, {sweep[0]}); }).find("two or more"),
            std::string::npos);
  std::vector<LoopPose> still(3);
  EXPECT_NE(message([&] { swept_loop_surface(loop, still); }).find("does not move"),
            std::string::npos);
  std::vector<LoopPose> broken = sweep;
  broken[1].position.x() = std::nan("");
  EXPECT_NE(message([&] { swept_loop_surface(loop, broken); }).find("non-finite"),
            std::string::npos);
  broken = sweep;
  broken[0].rotation(0, 0) = 2.0;
  EXPECT_NE(message([&] { swept_loop_surface(loop, broken); }).find("orthonormal"),
            std::string::npos);
  EXPECT_NE(message([&] {
              planar_cut_surface(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitZ(), 1, 1);
            }).find("parallel"),
            std::string::npos);
  EXPECT_NE(message([&] {
              scissor_cut_surface(Vec3::Zero(), Vec3::UnitX(), 2 * Vec3::UnitX());
            }).find("collinear"),
            std::string::npos);
}

}  // namespace
}  // namespace viscera::sim::cutting
