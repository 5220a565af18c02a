#include "simulator/session/severed_pieces.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "simulator/world/world.h"
#include "templates/template_catalog.h"
#include "tests/simulator/sim_fixtures.h"

namespace viscera::sim {
namespace {

/// Two separate blocks in one mesh: a 2 × 1 × 1 cm one, then a 1 × 1 × 1 cm one beside it.
core::TetMesh two_pieces(std::size_t& first_of_second) {
  core::TetMesh mesh = viscera::testing::tet_block(2, 1, 1, 0.01);
  const core::TetMesh small = viscera::testing::tet_block(1, 1, 1, 0.01);
  first_of_second = mesh.nodes.size();
  for (const auto& p : small.nodes)
    mesh.nodes.push_back(p + core::Vec3(0.05, 0.0, 0.0));
  for (auto t : small.tets) {
    for (int& v : t)
      v += static_cast<int>(first_of_second);
    mesh.tets.push_back(t);
  }
  return mesh;
}

TEST(SeveredPieces, the_piece_without_a_hold_is_severed) {
  std::size_t second = 0;
  const core::TetMesh mesh = two_pieces(second);
  // Held by a node of the small piece: the big one is cut off.
  std::vector<std::uint8_t> held(mesh.nodes.size(), 0);
  held[second + 1] = 1;
  const auto severed = severed_nodes(mesh, held);
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
    EXPECT_EQ(severed[n], n < second ? 1 : 0) << "node " << n;
}

TEST(SeveredPieces, a_body_held_nowhere_keeps_its_largest_piece) {
  std::size_t second = 0;
  const core::TetMesh mesh = two_pieces(second);
  const auto severed = severed_nodes(mesh, std::vector<std::uint8_t>(mesh.nodes.size(), 0));
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
    EXPECT_EQ(severed[n], n < second ? 0 : 1) << "node " << n;
}

TEST(SeveredPieces, a_pathology_is_held_by_its_attachments_and_the_wall_by_its_fixed_nodes) {
  const World world(templates::build_from_template("hysteroscopy", {}, 1));
  const auto count = [](const std::vector<std::uint8_t>& flags) {
    return std::count(flags.begin(), flags.end(), std::uint8_t{1});
  };
  // The wall: exactly its fixed nodes.
  const int uterus = world.body_index("uterus");
  const auto wall = world.held_nodes(uterus);
  const auto inverse = world.state().range(world.state().inverse_masses, uterus);
  EXPECT_EQ(count(wall), std::count(inverse.begin(), inverse.end(), 0.0));
  EXPECT_GT(count(wall), 0);
  // The polyp: its base nodes attached in the wall's tets, not its free head.
  const int polyp = world.body_index("polyp-1");
  const auto base = world.held_nodes(polyp);
  EXPECT_GT(count(base), 0);
  EXPECT_LT(count(base), static_cast<long>(base.size()) / 2);
  // The myoma: the nodes of its connection springs to the wall.
  const auto myoma = world.held_nodes(world.body_index("myoma-1"));
  EXPECT_GT(count(myoma), 0);
  // Uncut, nothing is severed.
  const auto& polyp_mesh = world.models()[static_cast<std::size_t>(polyp)]->mesh;
  EXPECT_EQ(count(severed_nodes(polyp_mesh, base)), 0);
}

}  // namespace
}  // namespace viscera::sim
