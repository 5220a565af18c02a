#include "simulator/cutting/fragments.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "tests/support/tet_block.h"

namespace viscera::sim::cutting {
namespace {

TEST(Fragments, two_separate_blocks_are_two_fragments_with_their_volumes) {
  core::TetMesh a = testing::tet_block(2, 1, 1, 0.01);
  const core::TetMesh b = testing::tet_block(1, 1, 1, 0.02);
  const int offset = static_cast<int>(a.nodes.size());
  for (const auto& p : b.nodes)
    a.nodes.push_back(p + core::Vec3(0.1, 0, 0));
  for (auto t : b.tets) {
    for (int& v : t)
      v += offset;
    a.tets.push_back(t);
  }
  a.surface_faces = core::boundary_faces(a.tets);
  a.fixed.assign(a.nodes.size(), 0);
  a.fixed[0] = 1;  // the first block is held
  const auto fragments = body_fragments(a);
  ASSERT_EQ(fragments.size(), 2u);
  EXPECT_NEAR(fragments[0].rest_volume, 2e-6, 1e-18);
  EXPECT_NEAR(fragments[1].rest_volume, 8e-6, 1e-18);
  EXPECT_TRUE(fragments[0].anchored);
  EXPECT_FALSE(fragments[1].anchored);
  EXPECT_EQ(fragments[0].tets.size(), 12u);
  EXPECT_EQ(fragments[1].nodes.size(), 8u);
  const auto chips = excised_chips(a);
  ASSERT_EQ(chips.size(), 1u);
  EXPECT_EQ(chips[0].tets, fragments[1].tets);
  // The chip as a body of its own.
  std::vector<int> map;
  const core::TetMesh chip = fragment_mesh(a, chips[0], &map);
  EXPECT_EQ(chip.nodes.size(), 8u);
  EXPECT_EQ(chip.surface_faces.size(), 12u);
  EXPECT_NEAR(core::total_volume(chip), 8e-6, 1e-18);
  EXPECT_EQ(map.front(), offset);
  // Caller anchors instead of fixed flags.
  std::vector<std::uint8_t> anchors(a.nodes.size(), 0);
  anchors[offset] = 1;
  EXPECT_EQ(excised_chips(a, anchors).size(), 1u);
  EXPECT_EQ(excised_chips(a, anchors)[0].tets, fragments[0].tets);
  EXPECT_THROW(body_fragments(a, std::vector<std::uint8_t>(3, 0)), core::InputError);
}

}  // namespace
}  // namespace viscera::sim::cutting
