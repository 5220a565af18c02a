// A tip that follows the tissue (InstrumentState::follow): the displacement of the nodes
// nearest the anchor, the named body, blending between waypoints, and the script's "follow".

#include "simulator/session/tissue_follow.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "simulator/session/instrument_input.h"
#include "simulator/world/world.h"
#include "tests/support/tet_block.h"

namespace viscera::sim {
namespace {

TEST(TissueFollow, the_displacement_is_the_mean_over_the_nodes_nearest_the_anchor) {
  World world(viscera::testing::held_soft_block());
  BodyView& block = world.bodies()[0];
  const core::Vec3 shift(0.001, -0.002, 0.0005);
  for (auto& p : block.positions())
    p += shift;
  // The corner node (0, 0, 0) is the only one at the anchor; its three neighbours 1 cm away
  // come next, farther ones after.
  const core::Vec3 anchor(-0.0001, -0.0001, -0.0001);
  EXPECT_TRUE(displacement_near(block, anchor).isApprox(shift, 1e-12));
  const auto rest = block.rest_positions();
  std::size_t corner = 0;
  for (std::size_t i = 0; i < rest.size(); ++i)
    if ((rest[i] - anchor).norm() < (rest[corner] - anchor).norm()) corner = i;
  const core::Vec3 extra(0.004, 0.0, 0.0);
  block.positions()[corner] += extra;
  EXPECT_TRUE(displacement_near(block, anchor, 4).isApprox(shift + extra / 4.0, 1e-12));
  EXPECT_TRUE(displacement_near(block, anchor, 1).isApprox(shift + extra, 1e-12));
}

TEST(TissueFollow, only_a_following_tip_moves_and_by_its_share) {
  World world(viscera::testing::held_soft_block());
  const core::Vec3 shift(0.0, 0.0, -0.001);
  for (auto& p : world.bodies()[0].positions())
    p += shift;
  InstrumentState input;
  input.tip = {0.01, 0.01, 0.03};
  input.anchor = {0.02, 0.02, 0.02};
  const auto tip_of = [&](const InstrumentState& s, const BodyView* instrument_body) {
    return followed(s, world.bodies(), instrument_body).tip;
  };
  EXPECT_EQ(tip_of(input, &world.bodies()[0]), input.tip);  // follow 0
  input.follow = 0.5;
  EXPECT_TRUE(tip_of(input, &world.bodies()[0]).isApprox(input.tip + 0.5 * shift, 1e-12));
  EXPECT_EQ(tip_of(input, nullptr), input.tip);  // no body to follow
  input.anchor_body = "block";
  EXPECT_TRUE(tip_of(input, nullptr).isApprox(input.tip + 0.5 * shift, 1e-12));
  input.anchor_body = "myoma";  // a body the world lacks
  EXPECT_EQ(tip_of(input, &world.bodies()[0]), input.tip);
}

TEST(TissueFollow, waypoints_blend_their_anchors_on_one_body_and_lend_them_otherwise) {
  InstrumentState a, b;
  b.follow = 1.0;
  b.anchor = {0.0, 0.0, 0.01};
  b.anchor_body = "polyp-1";
  // From a tip that does not follow to one that does: the share grows, the anchor is b's.
  InstrumentState s = blend(a, b, 0.25);
  EXPECT_DOUBLE_EQ(s.follow, 0.25);
  EXPECT_EQ(s.anchor, b.anchor);
  EXPECT_EQ(s.anchor_body, "polyp-1");
  // Two anchors on one body blend.
  a = b;
  a.anchor = {0.0, 0.0, 0.03};
  s = blend(a, b, 0.5);
  EXPECT_TRUE(s.anchor.isApprox(core::Vec3(0.0, 0.0, 0.02)));
  // On two bodies the nearer waypoint's holds.
  a.anchor_body = "uterus";
  EXPECT_EQ(blend(a, b, 0.4).anchor_body, "uterus");
  EXPECT_EQ(blend(a, b, 0.6).anchor_body, "polyp-1");
}

TEST(TissueFollow, a_following_place_anchors_its_waypoint_on_the_landmark_and_its_object) {
  const std::vector<core::Landmark> marks = {
      {"polyp-1-base", "base", "polyp-1", core::Vec3(0.0, 0.0, 0.01), core::Vec3::UnitZ()}};
  nlohmann::json script = {{"format", "viscera-script"}, {"version", 2}};
  script["waypoints"] = nlohmann::json::array();
  for (const double t : {0.0, 1.0})
    script["waypoints"].push_back(
        {{"t", t}, {"tip", {{"landmark", "polyp-1-base"}, {"frame", {0.0, 0.0, 0.002}}}}});
  script["waypoints"][1]["tip"]["follow"] = true;
  const auto resolved = resolve_script_landmarks(script, marks, "s.json");
  EXPECT_FALSE(resolved["waypoints"][0].contains("tip_anchor"));
  const auto trajectory = ScriptedTrajectory::from_json(resolved, "s.json");
  const InstrumentState end = trajectory.state(0, 1.0);
  EXPECT_EQ(end.follow, 1.0);
  EXPECT_EQ(end.anchor, core::Vec3(0.0, 0.0, 0.01));
  EXPECT_EQ(end.anchor_body, "polyp-1");
  EXPECT_TRUE(end.tip.isApprox(core::Vec3(0.0, 0.0, 0.012)));
  EXPECT_EQ(trajectory.state(0, 0.0).follow, 0.0);
  // An anchor that is not a point is refused with its place.
  nlohmann::json bad = resolved;
  bad["waypoints"][1]["tip_anchor"] = {0.0, "x", 0.0};
  EXPECT_THROW((void)ScriptedTrajectory::from_json(bad, "s.json"), core::InputError);
}

}  // namespace
}  // namespace viscera::sim
