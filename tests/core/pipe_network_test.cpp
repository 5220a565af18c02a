#include "core/modelling/pipe_network.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "tests/core/primitive_checks.h"

namespace viscera::core {
namespace {

using testing::is_watertight_and_outward;

/// A straight root along x with a perpendicular child leaving its middle along y.
PipeNetwork tee(double blend) {
  PipeNetwork network =
      make_pipe_network({{0, 0, 0}, {0.05, 0, 0}, {0.1, 0, 0}}, {0.005, 0.005, 0.005});
  network.branches.push_back({{{0.05, 0.02, 0}, {0.05, 0.04, 0}}, {0.003, 0.003}, 0, 0.5});
  network.start_cap = network.end_cap = PipeCap::Round;
  network.blend = blend;
  network.ring_segments = 32;
  return network;
}

TEST(PipeNetwork, tee_junction_is_watertight_with_the_volume_of_the_union) {
  const SurfaceMesh mesh = tessellate_pipe_network(tee(0.6));
  EXPECT_TRUE(is_watertight_and_outward(mesh));
  const double r = 0.005, rc = 0.003, pi = std::numbers::pi;
  // Root capsule, plus the child outside the root (from the wall to its round end).
  const double root = pi * r * r * 0.1 + 4.0 / 3.0 * pi * r * r * r;
  const double child_outside = pi * rc * rc * (0.04 - r) + 2.0 / 3.0 * pi * rc * rc * rc;
  EXPECT_LT(std::abs(enclosed_volume(mesh) / (root + child_outside) - 1.0), 0.03)
      << enclosed_volume(mesh);
  ASSERT_TRUE(mesh.vertex_attributes.contains("branch"));
  EXPECT_EQ(mesh.vertex_attributes.at("branch").size(), mesh.vertices.size());
}

TEST(PipeNetwork, fairing_turns_the_junction_crease_into_a_fillet) {
  const SurfaceMesh sharp = tessellate_pipe_network(tee(0.0));
  const SurfaceMesh smooth = tessellate_pipe_network(tee(0.8));
  EXPECT_TRUE(is_watertight_and_outward(sharp));
  EXPECT_TRUE(is_watertight_and_outward(smooth));
  const double sharp_turn = testing::max_dihedral_turn(sharp),
               smooth_turn = testing::max_dihedral_turn(smooth);
  EXPECT_GT(sharp_turn, 1.2);  // the bare union meets at a right angle
  EXPECT_LT(smooth_turn, 0.5 * sharp_turn) << smooth_turn;
}

TEST(PipeNetwork, y_bifurcation_at_the_parent_end_and_control_point_indexing) {
  PipeNetwork network = make_pipe_network({{0, 0, 0}, {0, 0, 0.04}}, {0.004, 0.004});
  network.branches.push_back({{{0.01, 0, 0.055}, {0.02, 0, 0.07}}, {0.003, 0.0025}, 0, 1.0});
  network.branches.push_back(
      {{{-0.01, 0.002, 0.055}, {-0.02, 0.004, 0.07}}, {0.003, 0.0025}, 0, 1.0});
  network.end_cap = PipeCap::Round;
  const SurfaceMesh mesh = tessellate_pipe_network(network);
  EXPECT_TRUE(is_watertight_and_outward(mesh));
  EXPECT_EQ(network_control_points(network).size(), 6u);
  EXPECT_EQ(locate_control_point(network, 3), std::make_pair(1, 1));
  EXPECT_THROW(locate_control_point(network, 6), UsageError);
  EXPECT_LT((attach_point(network, 1) - Vec3(0, 0, 0.04)).norm(), 1e-12);
  // Moving the root's end carries both children's starts with it.
  network.branches[0].points[1] = Vec3(0.005, 0, 0.045);
  EXPECT_LT((attach_point(network, 2) - Vec3(0.005, 0, 0.045)).norm(), 1e-12);
  EXPECT_TRUE(is_watertight_and_outward(tessellate_pipe_network(network)));
}

TEST(PipeNetwork, rejects_bad_parents_and_open_branching_ends) {
  PipeNetwork network = tee(0.5);
  network.branches[1].parent = 1;
  EXPECT_THROW(tessellate_pipe_network(network), UsageError);
  network = tee(0.5);
  network.branches[1].attach = 1.5;
  EXPECT_THROW(tessellate_pipe_network(network), UsageError);
  network = tee(0.5);
  network.end_cap = PipeCap::Open;
  EXPECT_THROW(tessellate_pipe_network(network), UsageError);
}

}  // namespace
}  // namespace viscera::core
