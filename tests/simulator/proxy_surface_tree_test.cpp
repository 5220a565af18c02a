#include "simulator/haptics/proxy_surface_tree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "core/primitives/icosphere.h"
#include "simulator/collision/penetration_depth.h"
#include "simulator/haptics/haptic_proxy.h"
#include "tests/simulator/sim_fixtures.h"

namespace viscera::sim {
namespace {

/// Every triangle tested in order, as HapticProxy did before the tree: the reference answers.
ProxySurfaceTree::Entry first_entry_of_every_face(const core::Vec3& p, const core::Vec3& q,
                                                  std::span<const core::Triangle> faces,
                                                  std::span<const core::Vec3> x) {
  ProxySurfaceTree::Entry best{-1, std::numeric_limits<double>::infinity()};
  for (std::size_t t = 0; t < faces.size(); ++t) {
    const core::Vec3 &a = x[faces[t][0]], &b = x[faces[t][1]], &c = x[faces[t][2]];
    if ((q - p).dot((b - a).cross(c - a)) >= 0.0) continue;
    const double s = segment_triangle_intersection(p, q, a, b, c);
    if (s >= 0.0 && s < best.s) best = {static_cast<int>(t), s};
  }
  return best;
}

int crossings_of_every_face(const core::Vec3& p, const core::Vec3& q,
                            std::span<const core::Triangle> faces, std::span<const core::Vec3> x) {
  int count = 0;
  for (const auto& f : faces)
    count += segment_triangle_intersection(p, q, x[f[0]], x[f[1]], x[f[2]]) >= 0.0 ? 1 : 0;
  return count;
}

/// A 2 cm sphere of 1,280 triangles, a sheet of 800 below it, one surface in one numbering.
struct TwoBodies {
  std::vector<core::Triangle> faces;
  std::vector<core::Vec3> positions;
};

TwoBodies sphere_over_a_sheet() {
  TwoBodies out;
  const core::SurfaceMesh sphere = core::make_icosphere(0.02, 3);
  const viscera::testing::Sheet sheet = viscera::testing::make_sheet(20, 0.05);
  out.positions = sheet.positions;
  out.faces = sheet.faces;
  const int offset = static_cast<int>(out.positions.size());
  for (const core::Vec3& p : sphere.vertices)
    out.positions.push_back(p + core::Vec3(0.0, 0.0, 0.025));
  for (core::Triangle f : sphere.triangles) {
    for (int& v : f)
      v += offset;
    out.faces.push_back(f);
  }
  return out;
}

TEST(ProxySurfaceTree, finds_the_same_first_entry_and_crossings_as_testing_every_triangle) {
  TwoBodies scene = sphere_over_a_sheet();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> in_box(-0.05, 0.05), wobble(-0.002, 0.002);
  ProxySurfaceTree tree(scene.faces, scene.positions);
  int entries = 0, odd = 0;
  for (int round = 0; round < 3; ++round) {
    for (int k = 0; k < 400; ++k) {
      const core::Vec3 p(in_box(random), in_box(random), in_box(random) + 0.02);
      // Short paths (a tip's step) and long ones (across the scene), and the parity ray.
      const core::Vec3 q =
          k % 2 == 0
              ? core::Vec3(p + 0.1 * core::Vec3(in_box(random), in_box(random), in_box(random)))
              : core::Vec3(in_box(random), in_box(random), in_box(random));
      const auto expected = first_entry_of_every_face(p, q, scene.faces, scene.positions);
      const auto found = tree.first_entry(p, q, scene.faces, scene.positions);
      ASSERT_EQ(found.face, expected.face) << "round " << round << " path " << k;
      if (found.face >= 0) {
        EXPECT_EQ(found.s, expected.s);
        ++entries;
      }
      const core::Vec3 far =
          p + 1.0e3 * core::Vec3(0.5773502691896257, 0.5773662691896258, 0.5773342691896259);
      const int crossings = tree.crossings(p, far, scene.faces, scene.positions);
      ASSERT_EQ(crossings, crossings_of_every_face(p, far, scene.faces, scene.positions));
      odd += crossings % 2;
    }
    // The surfaces move (the sphere sags onto the sheet, the sheet ripples): refitted now, or
    // by the next query once marked moved — the same answers either way.
    for (core::Vec3& x : scene.positions)
      x += core::Vec3(wobble(random), wobble(random), wobble(random) - 0.003);
    if (round == 0)
      tree.refit(scene.positions);
    else
      tree.mark_moved();
  }
  EXPECT_GT(entries, 100);  // the comparison saw many hits, not only misses
  EXPECT_GT(odd, 20);       // and many tips inside the sphere
}

TEST(ProxySurfaceTree,
     a_path_through_a_shared_vertex_or_along_an_edge_finds_what_every_face_finds) {
  // The sheet's vertices lie on a 5 mm lattice: paths straight down through vertices and down
  // the lattice's edges are the snapping cases of the box test (zero direction components).
  const viscera::testing::Sheet sheet = viscera::testing::make_sheet(20, 0.05);
  ProxySurfaceTree tree(sheet.faces, sheet.positions);
  const std::vector<core::Vec3> offsets = {core::Vec3(0.0, 0.0, 0.0), core::Vec3(0.0025, 0.0, 0.0)};
  for (const core::Vec3& v : sheet.positions) {
    for (const core::Vec3& offset : offsets) {
      const core::Vec3 p = v + offset + core::Vec3(0.0, 0.0, 0.01);
      const core::Vec3 q = v + offset - core::Vec3(0.0, 0.0, 0.01);
      const auto expected = first_entry_of_every_face(p, q, sheet.faces, sheet.positions);
      const auto found = tree.first_entry(p, q, sheet.faces, sheet.positions);
      ASSERT_EQ(found.face, expected.face);
      ASSERT_EQ(tree.crossings(p, q, sheet.faces, sheet.positions),
                crossings_of_every_face(p, q, sheet.faces, sheet.positions));
    }
  }
}

TEST(ProxySurfaceTree, the_proxy_takes_the_same_path_with_the_tree_as_without_it) {
  // A tip wandering into and out of the sphere: the proxy's position and contact at every step
  // are the same bits whether it searches every triangle or the tree.
  const TwoBodies scene = sphere_over_a_sheet();
  const ProxySurface surface(scene.faces);
  ProxySurfaceTree tree(scene.faces, scene.positions);
  HapticProxy plain(200.0), treed(200.0);
  const core::Vec3 start(0.0, 0.0, 0.06);
  plain.reset(start);
  treed.reset(start);
  int touching = 0;
  for (int k = 0; k < 2000; ++k) {
    const double t = 1e-3 * k;
    const core::Vec3 tip(0.015 * std::sin(3.1 * t), 0.012 * std::cos(2.3 * t),
                         0.03 + 0.03 * std::cos(1.7 * t));
    plain.update(tip, surface, scene.positions);
    plain.recapture(surface, scene.positions);
    treed.update(tip, surface, scene.positions, &tree);
    treed.recapture(surface, scene.positions, &tree);
    ASSERT_EQ(treed.contact().triangle, plain.contact().triangle) << "step " << k;
    ASSERT_EQ(treed.proxy(), plain.proxy()) << "step " << k;
    touching += plain.in_contact() ? 1 : 0;
  }
  EXPECT_GT(touching, 200);
  EXPECT_LT(touching, 1800);
}

}  // namespace
}  // namespace viscera::sim
