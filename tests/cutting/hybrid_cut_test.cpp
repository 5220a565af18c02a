#include "simulator/cutting/hybrid_cut.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.h"
#include "simulator/cutting/fragments.h"
#include "tests/cutting/cut_checks.h"
#include "tests/support/tet_block.h"

namespace viscera::sim::cutting {
namespace {

using core::Vec3;

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Vec3 v(g(rng), g(rng), g(rng));
  return v.normalized();
}

// Volume of the cap of a ball of radius r cut at distance d from its centre (the far side).
double cap_volume(double r, double d) {
  const double h = r - d;
  return M_PI * h * h * (3 * r - h) / 3.0;
}

TEST(HybridCut, hundred_random_planar_cuts_through_a_ball_keep_every_invariant) {
  const core::TetMesh& ball = testing::cutting_ball();
  const double radius = 0.02;
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> offset(-0.7 * radius, 0.7 * radius);
  const double total = core::total_volume(ball);
  for (int cut = 0; cut < 100; ++cut) {
    SCOPED_TRACE("planar cut " + std::to_string(cut));
    const Vec3 normal = random_unit(rng);
    const double d = offset(rng);
    const CutSurface plane =
        planar_cut_surface(d * normal, normal, random_unit(rng), 2 * radius, 2 * radius, 4);
    const TopologyChange change = hybrid_cut(ball, ball.nodes, plane);
    ASSERT_TRUE(change.changed);
    testing::expect_valid_cut(ball, ball.nodes, change);
    if (::testing::Test::HasFailure()) return;
    // Nodes made on cut edges (appended first) lie on the plane and slide only within it.
    for (std::size_t v = ball.nodes.size(); v < ball.nodes.size() + change.statistics.nodes_created;
         ++v) {
      EXPECT_NEAR((change.current[v] - d * normal).dot(normal), 0.0, 1e-12 * radius)
          << "node " << v;
    }
    const auto fragments = body_fragments(change.mesh);
    ASSERT_EQ(fragments.size(), 2u);
    // The piece on the normal's side is the cap beyond the plane (within the mesh's
    // approximation of the sphere: the polyhedron is inscribed, so allow 6 % of the ball).
    double plus_side = 0.0;
    for (const auto& f : fragments) {
      Vec3 centroid = Vec3::Zero();
      for (int v : f.nodes)
        centroid += change.mesh.nodes[v];
      if ((centroid / f.nodes.size()).dot(normal) > d) plus_side = f.rest_volume;
    }
    EXPECT_NEAR(plus_side, cap_volume(radius, d), 0.06 * total);
  }
}

TEST(HybridCut, hundred_random_loop_sweeps_through_a_ball_cut_off_a_chip) {
  const core::TetMesh& ball = testing::cutting_ball();
  const double radius = 0.02;
  std::mt19937_64 rng(2006);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int cut = 0; cut < 100; ++cut) {
    SCOPED_TRACE("loop sweep " + std::to_string(cut));
    // The loop hangs towards the centre from above the ball (its arms stay outside) and is
    // drawn across it along a path that bulges outwards, so the swept surface is curved.
    const Vec3 up = random_unit(rng);
    Vec3 along = random_unit(rng);
    along = (along - along.dot(up) * up).normalized();
    const double height = radius * (1.03 + 0.3 * unit(rng));
    LoopElectrode loop;
    loop.radius = (height - radius) + radius * (0.25 + 0.55 * unit(rng));
    loop.segments = 12;
    const double bulge = 0.2 * radius * unit(rng);
    const double reach = radius + loop.radius + 0.002;
    std::vector<LoopPose> sweep;
    for (int k = 0; k <= 12; ++k) {
      const double s = -reach + 2 * reach * k / 12.0;
      LoopPose pose;
      pose.position = (height + bulge * std::sin(M_PI * k / 12.0)) * up + s * along;
      pose.rotation.col(0) = up.cross(along);
      pose.rotation.col(1) = up;
      pose.rotation.col(2) = along;
      sweep.push_back(pose);
    }
    ASSERT_NO_THROW(require_sweep_leaves_tissue(ball, ball.nodes, loop, sweep));
    const TopologyChange change = hybrid_cut(ball, ball.nodes, swept_loop_surface(loop, sweep));
    ASSERT_TRUE(change.changed);
    testing::expect_valid_cut(ball, ball.nodes, change);
    if (::testing::Test::HasFailure()) return;
    const auto fragments = body_fragments(change.mesh);
    ASSERT_EQ(fragments.size(), 2u);
    // The chip is the smaller piece, on the loop's side.
    const double chip = std::min(fragments[0].rest_volume, fragments[1].rest_volume);
    EXPECT_GT(chip, 0.0);
    EXPECT_LT(chip, 0.5 * core::total_volume(ball));
  }
}

TEST(HybridCut, cuts_a_deformed_body_where_it_is_and_carries_the_rest_shape) {
  const core::TetMesh& ball = testing::cutting_ball();
  // A sheared deformation: the cut lives in the deformed configuration.
  std::vector<Vec3> current;
  for (const Vec3& p : ball.nodes)
    current.push_back(p + Vec3(0.4 * p.z(), 0.0, 0.1 * p.x()));
  const CutSurface plane =
      planar_cut_surface(Vec3(0.003, 0, 0), Vec3(1, 0.2, 0), Vec3(0, 0, 1), 0.05, 0.05, 6);
  const TopologyChange change = hybrid_cut(ball, current, plane);
  ASSERT_TRUE(change.changed);
  testing::expect_valid_cut(ball, current, change);
  // New nodes on the cut lie on the plane in the deformed configuration.
  const Vec3 n = Vec3(1, 0.2, 0).normalized();
  for (std::size_t v = ball.nodes.size(); v < change.current.size(); ++v) {
    if (change.statistics.nodes_relaxed == 0) {
      EXPECT_NEAR((change.current[v] - Vec3(0.003, 0, 0)).dot(n), 0.0, 1e-12);
    }
  }
}

TEST(HybridCut, a_plane_through_a_node_layer_separates_nodes_without_new_tets) {
  const core::TetMesh block = testing::tet_block(4, 4, 4, 0.01);
  for (double z : {0.02, 0.02 + 1e-9}) {
    const CutSurface plane =
        planar_cut_surface(Vec3(0.02, 0.02, z), Vec3::UnitZ(), Vec3::UnitX(), 0.05, 0.05, 2);
    const TopologyChange change = hybrid_cut(block, block.nodes, plane);
    ASSERT_TRUE(change.changed);
    testing::expect_valid_cut(block, block.nodes, change);
    EXPECT_EQ(change.statistics.nodes_created, 0u);
    EXPECT_EQ(change.statistics.tets_decomposed, 0u);
    EXPECT_EQ(change.statistics.nodes_duplicated, 25u);  // the 5 × 5 layer, once each
    EXPECT_EQ(change.mesh.tets.size(), block.tets.size());
    const auto fragments = body_fragments(change.mesh);
    ASSERT_EQ(fragments.size(), 2u);
    EXPECT_NEAR(fragments[0].rest_volume, 0.04 * 0.04 * 0.02, 1e-15);
    EXPECT_NEAR(fragments[1].rest_volume, 0.04 * 0.04 * 0.02, 1e-15);
    EXPECT_EQ(change.cut_surface_faces.size(), 2u * 32u);  // 16 squares, 2 triangles, 2 sides
  }
}

TEST(HybridCut, a_plane_along_tet_faces_separates_along_them) {
  // x = y holds the Kuhn tets' diagonal faces and every node with i = j.
  const core::TetMesh block = testing::tet_block(4, 4, 2, 0.01);
  const Vec3 normal = Vec3(1, -1, 0).normalized();
  const CutSurface plane =
      planar_cut_surface(Vec3(0.02, 0.02, 0.01), normal, Vec3::UnitZ(), 0.05, 0.05, 3);
  const TopologyChange change = hybrid_cut(block, block.nodes, plane);
  ASSERT_TRUE(change.changed);
  testing::expect_valid_cut(block, block.nodes, change);
  EXPECT_EQ(change.statistics.nodes_created, 0u);
  EXPECT_EQ(change.statistics.tets_decomposed, 0u);
  const auto fragments = body_fragments(change.mesh);
  ASSERT_EQ(fragments.size(), 2u);
  EXPECT_NEAR(fragments[0].rest_volume, 0.5 * core::total_volume(block), 1e-15);
}

TEST(HybridCut, a_plane_through_nodes_across_cells_decomposes_and_halves_exactly) {
  // x + y = 4 cm passes through nodes but crosses the Kuhn cells' interiors.
  const core::TetMesh block = testing::tet_block(4, 4, 2, 0.01);
  const Vec3 normal = Vec3(1, 1, 0).normalized();
  const CutSurface plane =
      planar_cut_surface(Vec3(0.02, 0.02, 0.01), normal, Vec3::UnitZ(), 0.05, 0.05, 3);
  const TopologyChange change = hybrid_cut(block, block.nodes, plane);
  ASSERT_TRUE(change.changed);
  testing::expect_valid_cut(block, block.nodes, change);
  EXPECT_GT(change.statistics.nodes_created, 0u);
  EXPECT_GT(change.statistics.nodes_snapped, 0u);
  const auto fragments = body_fragments(change.mesh);
  ASSERT_EQ(fragments.size(), 2u);
  EXPECT_NEAR(fragments[0].rest_volume, 0.5 * core::total_volume(block), 1e-12 * 1e-5);
}

TEST(HybridCut, carries_masses_fixed_flags_labels_and_velocities) {
  core::TetMesh block = testing::tet_block(3, 3, 3, 0.01);
  block.node_mass = core::lumped_node_masses(block, 1000.0);
  block.fixed.assign(block.nodes.size(), 0);
  for (std::size_t v = 0; v < block.nodes.size(); ++v)
    block.fixed[v] = block.nodes[v].z() < 1e-9;
  block.tet_labels.assign(block.tets.size(), 0);
  for (std::size_t t = 0; t < block.tets.size(); ++t)
    block.tet_labels[t] = static_cast<int>(t % 3);
  const CutSurface plane = planar_cut_surface(Vec3(0.015, 0.015, 0.013), Vec3(0.2, 0.1, 1),
                                              Vec3::UnitX(), 0.05, 0.05, 4);
  const TopologyChange change = hybrid_cut(block, block.nodes, plane);
  ASSERT_TRUE(change.changed);
  testing::expect_valid_cut(block, block.nodes, change);
  double before = 0.0, after = 0.0;
  for (double m : block.node_mass)
    before += m;
  for (double m : change.mesh.node_mass)
    after += m;
  EXPECT_NEAR(after, before, 1e-12 * before);
  ASSERT_EQ(change.mesh.tet_labels.size(), change.mesh.tets.size());
  for (std::size_t t = 0; t < change.mesh.tets.size(); ++t) {
    EXPECT_EQ(change.mesh.tet_labels[t], block.tet_labels[change.tet_parent[t]]);
  }
  ASSERT_EQ(change.mesh.fixed.size(), change.mesh.nodes.size());
  for (std::size_t v = 0; v < change.mesh.nodes.size(); ++v) {
    EXPECT_EQ(change.mesh.fixed[v] != 0, change.mesh.nodes[v].z() < 1e-9) << "node " << v;
  }
  // A rigid velocity field is carried exactly.
  std::vector<Vec3> velocity;
  for (const Vec3& p : block.nodes)
    velocity.push_back(Vec3(1, 2, 3) + Vec3(0, 0, 1).cross(p));
  const auto carried = carry_node_values(change, velocity);
  for (std::size_t v = 0; v < carried.size(); ++v) {
    EXPECT_LT((carried[v] - (Vec3(1, 2, 3) + Vec3(0, 0, 1).cross(change.mesh.nodes[v]))).norm(),
              1e-12);
  }
  // The top fragment lost its fixed nodes: a chip.
  const auto chips = excised_chips(change.mesh);
  ASSERT_EQ(chips.size(), 1u);
}

TEST(HybridCut, is_deterministic) {
  const core::TetMesh& ball = testing::cutting_ball();
  const CutSurface plane =
      planar_cut_surface(Vec3(0.001, 0.002, 0), Vec3(1, 2, 3), Vec3::UnitX(), 0.05, 0.05, 5);
  const TopologyChange a = hybrid_cut(ball, ball.nodes, plane);
  const TopologyChange b = hybrid_cut(ball, ball.nodes, plane);
  EXPECT_EQ(a.mesh, b.mesh);
  EXPECT_EQ(a.current, b.current);
  EXPECT_EQ(a.node_source, b.node_source);
  EXPECT_EQ(a.tet_parent, b.tet_parent);
}

TEST(HybridCut, a_surface_that_misses_the_body_changes_nothing) {
  const core::TetMesh block = testing::tet_block(2, 2, 2, 0.01);
  const CutSurface plane =
      planar_cut_surface(Vec3(0, 0, 0.5), Vec3::UnitZ(), Vec3::UnitX(), 0.05, 0.05, 2);
  const TopologyChange change = hybrid_cut(block, block.nodes, plane);
  EXPECT_FALSE(change.changed);
  EXPECT_EQ(change.mesh, block);
  EXPECT_EQ(change.statistics.tets_traversed, 0u);
}

TEST(HybridCut, an_incision_that_ends_inside_keeps_the_body_in_one_piece) {
  // Scissors closing on the middle of a block: the crack ends inside the tissue.
  const core::TetMesh block = testing::tet_block(6, 6, 2, 0.01);
  const CutSurface blades = scissor_cut_surface(
      Vec3(-0.01, 0.03, -0.005), Vec3(0.035, 0.03, -0.005), Vec3(0.035, 0.03, 0.025), 6);
  const TopologyChange change = hybrid_cut(block, block.nodes, blades);
  ASSERT_TRUE(change.changed);
  EXPECT_GT(change.cut_surface_faces.size(), 0u);
  EXPECT_EQ(body_fragments(change.mesh).size(), 1u);
  const double before = core::total_volume(block);
  EXPECT_NEAR(core::total_volume(change.mesh), before, 1e-9 * before);
  std::vector<core::Triangle> expected = core::boundary_faces(change.mesh.tets);
  EXPECT_EQ(expected.size(), change.mesh.surface_faces.size());
}

TEST(HybridCut, bad_input_gets_one_clear_sentence) {
  const core::TetMesh block = testing::tet_block(2, 2, 2, 0.01);
  const CutSurface plane =
      planar_cut_surface(Vec3(0.01, 0.01, 0.01), Vec3::UnitZ(), Vec3::UnitX(), 0.05, 0.05, 2);
  const auto message = [](auto&& call) {
    try {
      call();
    } catch (const core::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([&] { hybrid_cut(block, {}, plane); }).find("current positions"),
            std::string::npos);
  EXPECT_NE(message([&] { hybrid_cut(block, block.nodes, CutSurface{}); }).find("no triangles"),
            std::string::npos);
  CutSurface broken = plane;
  broken.vertices[0].x() = std::nan("");
  EXPECT_NE(message([&] { hybrid_cut(block, block.nodes, broken); }).find("not finite"),
            std::string::npos);
  std::vector<Vec3> moved = block.nodes;
  moved[3].y() = INFINITY;
  EXPECT_NE(message([&] { hybrid_cut(block, moved, plane); }).find("node 3"), std::string::npos);
  // A sweep that ends inside the tissue is refused before any cut.
  LoopElectrode loop;
  loop.radius = 0.005;
  std::vector<LoopPose> sweep(2);
  sweep[0].position = Vec3(-0.02, 0.01, 0.015);
  sweep[1].position = Vec3(0.01, 0.01, 0.015);
  sweep[0].rotation = sweep[1].rotation =
      (core::Mat3() << 0, 0, 1, 0, 1, 0, -1, 0, 0).finished();  // advance along +x
  const std::string inside =
      message([&] { require_sweep_leaves_tissue(block, block.nodes, loop, sweep); });
  EXPECT_NE(inside.find("ends inside the tissue"), std::string::npos) << inside;
}

}  // namespace
}  // namespace viscera::sim::cutting

namespace viscera::sim::cutting {
namespace {

TEST(HybridCut, a_surface_that_only_touches_the_skin_changes_nothing) {
  // A plane resting on the block's top face touches its nodes but separates nothing.
  const core::TetMesh block = testing::tet_block(2, 2, 2, 0.01);
  const CutSurface plane = planar_cut_surface(core::Vec3(0.01, 0.01, 0.02), core::Vec3::UnitZ(),
                                              core::Vec3::UnitX(), 0.05, 0.05, 2);
  const TopologyChange change = hybrid_cut(block, block.nodes, plane);
  EXPECT_FALSE(change.changed);
  EXPECT_EQ(change.mesh, block);
  EXPECT_GT(change.statistics.nodes_snapped, 0u);
}

}  // namespace
}  // namespace viscera::sim::cutting

namespace viscera::sim::cutting {
namespace {

TEST(HybridCut, successive_cuts_through_earlier_cut_faces_keep_every_invariant) {
  // Stepwise shaving: each cut runs on the result of the last one, across its cut faces.
  core::TetMesh body = testing::cutting_ball();
  std::vector<core::Vec3> current = body.nodes;
  std::mt19937_64 rng(3);
  std::size_t pieces = 1;
  for (int cut = 0; cut < 6; ++cut) {
    SCOPED_TRACE("cut " + std::to_string(cut));
    const core::Vec3 normal = random_unit(rng);
    const CutSurface plane =
        planar_cut_surface(0.004 * (cut % 3 - 1) * normal, normal, random_unit(rng), 0.05, 0.05, 3);
    const TopologyChange change = hybrid_cut(body, current, plane);
    ASSERT_TRUE(change.changed);
    testing::expect_valid_cut(body, current, change);
    if (::testing::Test::HasFailure()) return;
    const std::size_t now = body_fragments(change.mesh).size();
    EXPECT_GT(now, pieces);
    pieces = now;
    body = change.mesh;
    current = change.current;
  }
}

}  // namespace
}  // namespace viscera::sim::cutting
