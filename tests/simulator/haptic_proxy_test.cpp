#include "simulator/haptics/haptic_proxy.h"

#include <gtest/gtest.h>

#include "core/primitives/icosphere.h"
#include "simulator/haptics/device_limits.h"
#include "tests/simulator/sim_fixtures.h"

namespace viscera::sim {
namespace {

/// A flat sheet at z = 0 facing +z, 10 cm wide, in 20 × 20 squares.
viscera::testing::Sheet make_sheet() {
  return viscera::testing::make_sheet(20, 0.05);
}

TEST(ProxySurface, finds_the_triangle_across_every_edge_and_none_across_a_border) {
  // A closed sphere: every edge has the neighbour that runs it the other way.
  const core::SurfaceMesh sphere = core::make_icosphere(0.02, 2);
  const ProxySurface closed(sphere.triangles);
  for (int t = 0; t < static_cast<int>(sphere.triangles.size()); ++t)
    for (int e = 0; e < 3; ++e) {
      const int across = closed.neighbour(t, e);
      ASSERT_GE(across, 0);
      ASSERT_NE(across, t);
      const auto& f = sphere.triangles[static_cast<std::size_t>(t)];
      const auto& g = sphere.triangles[static_cast<std::size_t>(across)];
      bool reversed = false;
      for (int d = 0; d < 3; ++d)
        reversed = reversed || (g[d] == f[(e + 1) % 3] && g[(d + 1) % 3] == f[e]);
      EXPECT_TRUE(reversed);
    }
  // The open sheet: 4·20 border edges have none, every other edge has one.
  const viscera::testing::Sheet sheet = make_sheet();
  const ProxySurface open(sheet.faces);
  int border = 0;
  for (int t = 0; t < static_cast<int>(sheet.faces.size()); ++t)
    for (int e = 0; e < 3; ++e)
      border += open.neighbour(t, e) < 0 ? 1 : 0;
  EXPECT_EQ(border, 80);
}

TEST(ProxySurface, joined_parts_keep_their_adjacency_in_global_numbers) {
  // A sheet (441 vertices) then a sphere numbered after it: the joined surface's adjacency is
  // what a search over all its faces finds.
  const viscera::testing::Sheet sheet = make_sheet();
  const core::SurfaceMesh sphere = core::make_icosphere(0.02, 1);
  const std::vector<ProxySurface> parts = {ProxySurface(sheet.faces),
                                           ProxySurface(sphere.triangles)};
  const std::vector<int> offsets = {0, static_cast<int>(sheet.positions.size())};
  const ProxySurface joined = ProxySurface::joined(parts, offsets);
  std::vector<core::Triangle> all = sheet.faces;
  for (core::Triangle f : sphere.triangles) {
    for (int& v : f)
      v += offsets[1];
    all.push_back(f);
  }
  const ProxySurface searched(all);
  ASSERT_EQ(joined.faces(), searched.faces());
  for (int t = 0; t < static_cast<int>(all.size()); ++t)
    for (int e = 0; e < 3; ++e)
      EXPECT_EQ(joined.neighbour(t, e), searched.neighbour(t, e));
}

TEST(HapticProxy, stays_on_the_surface_above_the_tip_with_a_spring_force) {
  const viscera::testing::Sheet sheet = make_sheet();
  const ProxySurface surface(sheet.faces);
  HapticProxy proxy(200.0);
  proxy.reset({0.001, 0.002, 0.01});
  proxy.update({0.001, 0.002, 0.005}, surface, sheet.positions);
  EXPECT_FALSE(proxy.in_contact());
  EXPECT_EQ(proxy.force(), core::Vec3::Zero());
  proxy.update({0.001, 0.002, -0.004}, surface, sheet.positions);
  ASSERT_TRUE(proxy.in_contact());
  EXPECT_NEAR(proxy.proxy().z(), 0.0, 1e-15);
  EXPECT_NEAR(proxy.proxy().x(), 0.001, 1e-15);
  EXPECT_TRUE(proxy.force().isApprox(core::Vec3(0, 0, 200.0 * 0.004), 1e-12));
}

TEST(HapticProxy, slides_across_triangles_and_its_force_changes_continuously) {
  const viscera::testing::Sheet sheet = make_sheet();
  const ProxySurface surface(sheet.faces);
  HapticProxy proxy(300.0);
  proxy.reset({-0.04, 0.0013, 0.01});
  proxy.update({-0.04, 0.0013, -0.003}, surface, sheet.positions);
  ASSERT_TRUE(proxy.in_contact());
  core::Vec3 previous_force = proxy.force();
  core::Vec3 tip(-0.04, 0.0013, -0.003);
  const core::Vec3 step(0.0001, 0.00003, -0.00001);  // drag across many triangles, pressing deeper
  for (int s = 0; s < 700; ++s) {
    tip += step;
    proxy.update(tip, surface, sheet.positions);
    ASSERT_TRUE(proxy.in_contact()) << s;
    EXPECT_NEAR(proxy.proxy().z(), 0.0, 1e-12) << s;
    EXPECT_NEAR(proxy.proxy().x(), tip.x(), 1e-12) << s;  // the nearest surface point
    EXPECT_LE((proxy.force() - previous_force).norm(), 300.0 * step.norm() + 1e-12) << s;
    previous_force = proxy.force();
  }
  EXPECT_GT(proxy.contact().triangle, 100);  // it walked far from where it started
}

TEST(HapticProxy, is_released_when_the_tip_comes_back_out) {
  const viscera::testing::Sheet sheet = make_sheet();
  const ProxySurface surface(sheet.faces);
  HapticProxy proxy(100.0);
  proxy.reset({0.0, 0.0, 0.01});
  proxy.update({0.0, 0.0, -0.002}, surface, sheet.positions);
  ASSERT_TRUE(proxy.in_contact());
  proxy.update({0.003, 0.0, 0.004}, surface, sheet.positions);
  EXPECT_FALSE(proxy.in_contact());
  EXPECT_EQ(proxy.proxy(), core::Vec3(0.003, 0.0, 0.004));
  EXPECT_EQ(proxy.force(), core::Vec3::Zero());
}

TEST(HapticProxy, pushed_into_a_sphere_the_proxy_stays_on_it_and_pushes_outward) {
  const core::SurfaceMesh sphere = core::make_icosphere(0.03, 4);
  const ProxySurface surface(sphere.triangles);
  HapticProxy proxy(150.0);
  const core::Vec3 direction = core::Vec3(0.3, -0.2, 1.0).normalized();
  proxy.reset(0.05 * direction);
  for (double r = 0.05; r >= 0.02; r -= 0.0005) {
    const core::Vec3 tip = r * direction + core::Vec3(0.0, 0.0002 * (0.05 - r) / 0.0005, 0.0);
    proxy.update(tip, surface, sphere.vertices);
    if (r < 0.0295) {
      ASSERT_TRUE(proxy.in_contact()) << r;
      EXPECT_NEAR(proxy.proxy().norm(), 0.03, 0.03 * 0.003) << r;  // on the faceted sphere
      EXPECT_GT(proxy.force().normalized().dot(proxy.proxy().normalized()), 0.99) << r;
    }
  }
}

TEST(HapticProxy, a_wall_that_swept_over_the_free_tip_recaptures_it_at_the_nearest_point) {
  const core::SurfaceMesh sphere = core::make_icosphere(0.03, 3);
  const ProxySurface surface(sphere.triangles);
  HapticProxy proxy(200.0);
  // Free just outside the sphere; then the sphere grows by 2 mm around the resting tip.
  const core::Vec3 tip(0.0312, 0.0004, -0.0002);
  proxy.reset(tip);
  proxy.update(tip, surface, sphere.vertices);
  EXPECT_FALSE(proxy.recapture(surface, sphere.vertices));
  std::vector<core::Vec3> grown = sphere.vertices;
  for (auto& v : grown)
    v *= 0.0320 / 0.03;
  proxy.update(tip, surface, grown);
  EXPECT_FALSE(proxy.in_contact());  // the path test sees no crossing: the tip did not move
  ASSERT_TRUE(proxy.recapture(surface, grown));
  EXPECT_TRUE(proxy.in_contact());
  EXPECT_GT(proxy.proxy().norm(), 0.0318);  // on the grown surface (inscribed faces dip a little)
  EXPECT_GT(proxy.force().dot(tip), 0.0);   // pushing the tool back out
  EXPECT_FALSE(proxy.recapture(surface, grown));  // in contact already
}

TEST(HapticProxy, the_reaction_spreads_to_the_triangle_nodes_by_barycentric_weights) {
  const auto parts = distribute_to_triangle({4, 7, 9}, {0.2, 0.3, 0.5}, core::Vec3(0, 0, -1.0));
  EXPECT_EQ(parts[0].first, 4);
  EXPECT_EQ(parts[2].first, 9);
  EXPECT_TRUE(
      (parts[0].second + parts[1].second + parts[2].second).isApprox(core::Vec3(0, 0, -1.0)));
  EXPECT_DOUBLE_EQ(parts[1].second.z(), -0.3);
}

TEST(DeviceLimits, clamp_force_and_torques_to_the_hysteroscopy_device) {
  const core::Vec3 axis = core::Vec3::UnitZ();
  auto out = clamp_to_device({3.0, 4.0, 0.0}, {0.0, 0.0, 0.0}, axis);
  EXPECT_NEAR(out.force.norm(), 2.0, 1e-12);
  EXPECT_TRUE(out.force_limited);
  EXPECT_TRUE(out.force.normalized().isApprox(core::Vec3(0.6, 0.8, 0.0)));
  out = clamp_to_device({0.01, 0.0, 0.0}, {0.0, 0.0, 0.0}, axis);
  EXPECT_EQ(out.force, core::Vec3::Zero());  // below the 0.04 N the drive can render
  out = clamp_to_device({0.5, 0.0, 0.0}, {1.2, 0.0, 0.1}, axis);
  EXPECT_EQ(out.force, core::Vec3(0.5, 0.0, 0.0));
  EXPECT_NEAR(out.torque.x(), 0.5, 1e-12);   // pitch/yaw ≤ 0.5 N·m
  EXPECT_NEAR(out.torque.z(), 0.02, 1e-12);  // roll ≤ 0.02 N·m
  EXPECT_TRUE(out.torque_limited);
}

}  // namespace
}  // namespace viscera::sim
