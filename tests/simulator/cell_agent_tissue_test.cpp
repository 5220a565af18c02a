#include "simulator/physics/cell_agent_tissue.h"

#include <gtest/gtest.h>

#include "core/random.h"

namespace viscera::sim {
namespace {

/// A 2D sheet of n × n cells 1 mm apart, with two cell types in stripes (heterogeneous).
CellAgentTissue sheet(int n, bool planar = true) {
  std::vector<core::Vec3> positions;
  std::vector<int> type_of;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      positions.emplace_back(0.001 * i, 0.001 * j, 0.0);
      type_of.push_back((j / 3) % 2);
    }
  CellType soft, stiff;
  stiff.connection_stiffness = 60.0;
  stiff.home_stiffness = 1.0;
  return CellAgentTissue(positions, {soft, stiff}, type_of, 0.00105, 4, planar);
}

TEST(CellAgentTissue, neighbour_discovery_links_the_four_grid_neighbours) {
  const CellAgentTissue tissue = sheet(10);
  // A 10 × 10 grid has 2 · 10 · 9 horizontal and vertical links; diagonals are out of reach.
  EXPECT_EQ(tissue.connections().size(), 180u);
  for (const auto& c : tissue.connections())
    EXPECT_NEAR(c.rest_length, 0.001, 1e-12);
}

TEST(CellAgentTissue, connection_forces_cancel_in_sum) {
  CellAgentTissue tissue = sheet(8);
  core::Rng rng(4);
  for (int k = 0; k < 10; ++k)
    tissue.drag(rng.uniform_int(0, 63), {rng.uniform(0, 0.008), rng.uniform(0, 0.008), 0.0});
  core::Vec3 net = core::Vec3::Zero();
  double magnitude = 0.0;
  for (const auto& f : tissue.connection_forces()) {
    net += f;
    magnitude += f.norm();
  }
  EXPECT_GT(magnitude, 0.0);
  EXPECT_LT(net.norm(), 1e-12 * magnitude);
}

TEST(CellAgentTissue, pulled_and_released_it_returns_home_and_rests) {
  CellAgentTissue tissue = sheet(8);
  const int grasped = 8 * 4 + 4;
  for (int s = 0; s < 200; ++s) {
    tissue.drag(grasped,
                tissue.homes()[grasped] + core::Vec3(0.0, 0.0005 * std::min(1.0, s / 100.0), 0.0));
    tissue.step(1e-3);
  }
  EXPECT_GT((tissue.positions()[grasped + 8] - tissue.homes()[grasped + 8]).norm(),
            1e-5);  // neighbours follow
  tissue.release(grasped);
  for (int s = 0; s < 20000; ++s)
    tissue.step(1e-3);
  double largest = 0.0, speed = 0.0;
  for (std::size_t i = 0; i < tissue.positions().size(); ++i) {
    largest = std::max(largest, (tissue.positions()[i] - tissue.homes()[i]).norm());
    speed = std::max(speed, tissue.velocities()[i].norm());
  }
  EXPECT_LT(largest, 1e-6);
  EXPECT_LT(speed, 1e-6);
  EXPECT_EQ(tissue.torn(), 0);
}

TEST(CellAgentTissue, a_cut_separates_the_two_sides) {
  CellAgentTissue tissue = sheet(8);
  // A blade standing across the sheet between columns 3 and 4 (x = 3.5 mm).
  const int cut = tissue.cut({0.0035, -0.1, -0.1}, {0.0035, 0.1, -0.1}, {0.0035, 0.0, 0.1});
  EXPECT_EQ(cut, 8);  // one horizontal link per row
  for (const auto& c : tissue.connections()) {
    EXPECT_EQ(tissue.positions()[c.a].x() < 0.0035, tissue.positions()[c.b].x() < 0.0035);
  }
  // Pulling the left side leaves the right side where it is.
  for (int s = 0; s < 300; ++s) {
    tissue.drag(8 * 4 + 1, tissue.homes()[8 * 4 + 1] + core::Vec3(-0.0005, 0.0, 0.0));
    tissue.step(1e-3);
  }
  EXPECT_LT((tissue.positions()[8 * 4 + 5] - tissue.homes()[8 * 4 + 5]).norm(), 1e-12);
}

TEST(CellAgentTissue, overstretched_connections_tear_and_stretched_ones_yield) {
  // A sheet well anchored to its homes, so pulling a corner stretches the corner's links.
  std::vector<core::Vec3> positions;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      positions.emplace_back(0.001 * i, 0.001 * j, 0.0);
  CellType anchored;
  anchored.home_stiffness = 200.0;
  CellAgentTissue tissue(positions, {anchored}, std::vector<int>(16, 0), 0.00105, 4, true);
  const int corner = 0;
  // Yield: stretch the corner's links by about 70 % (yield 50 %, tear 100 %).
  for (int s = 0; s < 50; ++s) {
    tissue.drag(corner, {-0.0007, -0.0007, 0.0});
    tissue.step(1e-3);
  }
  EXPECT_EQ(tissue.torn(), 0);
  double longest_rest = 0.0;
  for (const auto& c : tissue.connections())
    longest_rest = std::max(longest_rest, c.rest_length);
  EXPECT_GT(longest_rest, 0.00101);  // plastic: a rest length grew
  // Tear: pull the corner slowly further away until its links break.
  for (int s = 0; s < 1000; ++s) {
    tissue.drag(corner, core::Vec3(-0.0007, -0.0007, 0.0) * (1.0 + 4.0 * s / 1000.0));
    tissue.step(1e-3);
  }
  EXPECT_GE(tissue.torn(), 2);  // at least both links of the corner cell broke
  for (const auto& c : tissue.connections())
    EXPECT_TRUE(c.a != corner && c.b != corner);
}

TEST(CellAgentTissue, planar_sheets_stay_in_their_plane_and_volumes_move_in_3d) {
  CellAgentTissue flat = sheet(5, true);
  flat.push(12, {0.0, 0.0, 1.0});
  flat.step(1e-3);
  EXPECT_EQ(flat.positions()[12].z(), 0.0);
  CellAgentTissue volume = sheet(5, false);
  volume.push(12, {0.0, 0.0, 1.0});
  volume.step(1e-3);
  EXPECT_GT(volume.positions()[12].z(), 0.0);
}

}  // namespace
}  // namespace viscera::sim
