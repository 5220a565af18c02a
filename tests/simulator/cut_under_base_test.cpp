// A loop drawn under a polyp's base (issue 17 §4, §5): the surgeon takes a pedunculated polyp
// off at its base by passing the loop just beneath it, through the endometrium it grows from.
// The holds the loop passes under are cut with it, so the polyp comes off whole; a cut above
// the base leaves them.

#include "simulator/session/cut_under_base.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "simulator/session/loop_resection.h"
#include "simulator/session/severed_pieces.h"
#include "tests/support/polyp_scoop.h"

namespace viscera::sim {
namespace {

/// The hysteroscopy patient's polyp settled on its wall, with the wall's normal at its base.
struct SettledPolyp {
  World world;
  int body = -1;
  core::Vec3 base, normal;
  double deepest = 0.0, highest = 0.0;  ///< m, held nodes along the normal from the base
  explicit SettledPolyp(const core::Scenario& scenario) : world(scenario) {
    world.settle();
    const testing::PolypFrame frame = testing::polyp_frame(world);
    body = frame.body;
    base = frame.base;
    for (const auto& mark : scenario.landmarks)
      if (mark.id == "polyp-1-base") normal = mark.normal.normalized();
    const auto held = world.held_nodes(body);
    const auto x = world.state().range(world.state().positions, body);
    for (std::size_t i = 0; i < held.size(); ++i) {
      if (held[i] == 0) continue;
      deepest = std::min(deepest, (x[i] - base).dot(normal));
      highest = std::max(highest, (x[i] - base).dot(normal));
    }
  }
  /// A 1 cm square sheet parallel to the wall, `offset` m along its normal from the base.
  cutting::CutSurface sheet(double offset) const {
    return cutting::planar_cut_surface(base + offset * normal, normal, normal.unitOrthogonal(),
                                       0.005, 0.005, 8);
  }
  int held_count() const {
    const auto held = world.held_nodes(body);
    return static_cast<int>(std::count(held.begin(), held.end(), std::uint8_t{1}));
  }
};

TEST(CutUnderBase, a_sweep_half_a_millimetre_under_the_base_frees_the_polyp_whole) {
  SettledPolyp polyp(testing::resectoscope_patient());
  const int held = polyp.held_count();
  ASSERT_GE(held, 3) << "the polyp grows on the wall by several nodes";
  ASSERT_GT(polyp.highest - polyp.deepest, 0.0);
  const int released =
      release_cut_under(polyp.world, polyp.body, polyp.sheet(polyp.deepest - 5e-4));
  EXPECT_EQ(released, held);
  EXPECT_EQ(polyp.held_count(), 0);
  // Nothing holds it now: the whole polyp is one piece cut off, a chip of its full volume.
  const auto& mesh = polyp.world.models()[static_cast<std::size_t>(polyp.body)]->mesh;
  EXPECT_TRUE(severed_fragments(mesh, polyp.world.held_nodes(polyp.body)).empty())
      << "a body never held keeps its largest piece";
  const auto pieces = severed_fragments(mesh, polyp.world.held_nodes(polyp.body), true);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0].tets.size(), mesh.tets.size());
}

TEST(CutUnderBase, a_sweep_above_the_base_or_deeper_than_3_mm_under_it_frees_nothing) {
  SettledPolyp polyp(testing::resectoscope_patient());
  const int held = polyp.held_count();
  EXPECT_EQ(release_cut_under(polyp.world, polyp.body, polyp.sheet(polyp.highest + 5e-4)), 0);
  EXPECT_EQ(release_cut_under(polyp.world, polyp.body,
                              polyp.sheet(polyp.deepest - kUnderBaseDepth - 2e-3)),
            0);
  EXPECT_EQ(polyp.held_count(), held);
}

TEST(CutUnderBase, the_loop_drawn_along_the_wall_under_the_base_cuts_the_whole_polyp_off) {
  SettledPolyp polyp(testing::resectoscope_patient());
  LoopResection loop(polyp.world, {polyp.body}, standard_resection_loop());
  CuttingSummary summary;
  loop.begin(polyp.world, summary);
  std::vector<SessionEvent> events;
  // Drawn parallel to the wall, the loop's lowest point half a millimetre under the deepest node
  // that holds the polyp, from well beside the polyp to well past it (the world stands still:
  // only the loop's path matters here, not the sheath's).
  const core::Vec3 across = polyp.normal.unitOrthogonal();
  const core::Vec3 lowest = polyp.base + (polyp.deepest - 5e-4) * polyp.normal;
  InstrumentState state;
  state.axis = across;
  state.up = -polyp.normal;
  state.electrode = true;
  constexpr int kPoses = 60;
  constexpr double kReach = 0.008;  // m either side of the base
  for (int k = 0; k <= kPoses; ++k) {
    const double s = kReach * (1.0 - 2.0 * k / static_cast<double>(kPoses));
    state.tip = lowest + testing::kRadius * polyp.normal + s * across;
    loop.follow(state, polyp.world, 0.01 * k, summary, events);
  }
  state.electrode = false;
  loop.follow(state, polyp.world, 0.61, summary, events);
  const BodyResection& resection = summary.bodies.front();
  EXPECT_GE(resection.chips, 1);
  EXPECT_NEAR(resection.resected_fraction(), 1.0, 1e-9);
  EXPECT_TRUE(loop.lost_every_hold(polyp.world, polyp.body));
  EXPECT_TRUE(std::any_of(events.begin(), events.end(),
                          [](const auto& e) { return e.kind == "cut-under-base"; }));
}

}  // namespace
}  // namespace viscera::sim
