// How deep the loop cut into the wall (issue 17 §5): sheets swept at known depths under the
// fundus of the hysteroscopy patient's uterus measure as deep as they lie, one in the cavity
// does not enter the wall, one through the wall is a perforation, and a session whose loop cuts
// through the wall ends on it.

#include "simulator/session/wall_cut_depth.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "simulator/session/headless_session.h"
#include "simulator/session/instrument_input.h"
#include "simulator/session/instrument_state.h"
#include "tests/support/polyp_scoop.h"

namespace viscera::sim {
namespace {

/// The patient at rest (not settled: its positions are its rest shape, where the landmarks lie)
/// with the gauge on its uterus, at one of its wall's landmarks.
struct WallSpot {
  core::Scenario scenario = testing::resectoscope_patient();
  World world{scenario};
  core::Vec3 point, normal;  ///< the landmark; its normal points into the cavity
  std::unique_ptr<WallCutGauge> gauge;
  explicit WallSpot(const std::string& landmark = "fundus") {
    for (const auto& mark : scenario.landmarks)
      if (mark.id == landmark) point = mark.position, normal = mark.normal.normalized();
    const int uterus = world.body_index("uterus");
    gauge = std::make_unique<WallCutGauge>(uterus, cavity_surface(*scenario.find_object("uterus")));
  }
  /// A 2 mm square sheet parallel to the wall, `depth` m into it (negative: in the cavity).
  cutting::CutSurface sheet(double depth) const {
    return cutting::planar_cut_surface(point - depth * normal, normal, normal.unitOrthogonal(),
                                       0.001, 0.001, 8);
  }
};

TEST(WallCutDepth, sheets_under_the_fundus_measure_as_deep_as_they_lie) {
  const WallSpot f;
  const auto one = f.gauge->measure(f.world, f.sheet(0.001));
  const auto three = f.gauge->measure(f.world, f.sheet(0.003));
  ASSERT_TRUE(one && three);
  // The deepest point is a corner of the sheet, under the fundus's curve: a little deeper than
  // the sheet's centre; two sheets 2 mm apart are 2 mm apart in depth.
  EXPECT_GE(one->depth, 0.001 - 1e-4);
  EXPECT_LT(one->depth, 0.0015);
  EXPECT_NEAR(three->depth - one->depth, 0.002, 1e-4);
  EXPECT_FALSE(one->perforated || three->perforated);
  // The wall's thickness there: the same wall under both, several millimetres of it.
  EXPECT_GT(one->thickness, 0.005);
  EXPECT_LT(one->thickness, 0.03);
  EXPECT_NEAR(three->thickness, one->thickness, 1e-3);
  // The wall between each sheet and the cavity: 2 mm more of it under the deeper one, over the
  // sheet's 4 mm² (projected on the wall).
  EXPECT_NEAR(three->removed_volume - one->removed_volume, 4e-6 * 0.002, 0.05 * 8e-9);
}

TEST(WallCutDepth, a_sheet_in_the_cavity_does_not_enter_the_wall) {
  const WallSpot f;
  EXPECT_FALSE(f.gauge->measure(f.world, f.sheet(-0.001)).has_value());
}

TEST(WallCutDepth, a_sheet_through_the_wall_is_a_perforation) {
  const WallSpot f;
  const auto wall = f.gauge->measure(f.world, f.sheet(0.001));
  ASSERT_TRUE(wall);
  // Across the wall, from 2 mm in the cavity to 1 cm beyond the far side.
  const double reach = wall->thickness + 0.012;
  const cutting::CutSurface through =
      cutting::planar_cut_surface(f.point - 0.5 * (reach - 0.004) * f.normal,
                                  f.normal.unitOrthogonal(), f.normal, 0.5 * reach, 0.001, 16);
  const auto cut = f.gauge->measure(f.world, through);
  ASSERT_TRUE(cut);
  EXPECT_TRUE(cut->perforated);
  EXPECT_NEAR(cut->depth, cut->thickness, 1e-12);
}

/// The resectoscope 5 mm in front of the wall pointing at it, its loop stood out `depth` m into
/// the wall (the loop hangs across the shaft, parallel to the wall) and drawn 4 mm across it
/// with the cutting pedal down; 1 s.
SessionReport sweep_into_the_wall(const WallSpot& f, double depth) {
  const double extension = 0.005 + depth;
  EXPECT_LE(extension, kMaxLoopExtension);
  const core::Vec3 tip = f.point + 0.005 * f.normal, side = f.normal.unitOrthogonal();
  const auto point = [](const core::Vec3& p) { return nlohmann::json{p.x(), p.y(), p.z()}; };
  const nlohmann::json script = {
      {"format", "viscera-script"},
      {"version", 2},
      {"body", "uterus"},
      {"waypoints",
       {{{"t", 0.0},
         {"tip", point(tip)},
         {"axis", point(-f.normal)},
         {"up", point(side)},
         {"loop_extension", extension}},
        {{"t", 0.2}, {"tip", point(tip)}, {"activate", 1}},
        {{"t", 0.6}, {"tip", point(tip + 0.004 * side.cross(f.normal))}},
        {{"t", 0.62}, {"tip", point(tip + 0.004 * side.cross(f.normal))}, {"activate", 0}},
        {{"t", 1.0}, {"tip", point(tip + 0.004 * side.cross(f.normal))}}}}};
  const auto input = ScriptedTrajectory::from_json(script, "wall", 30.0);
  HeadlessRunOptions options;
  options.duration = 1.0;
  options.instrument = &input;
  options.instrument_body = "uterus";
  return run_headless(f.scenario, options);
}

TEST(WallCutDepth, a_loop_drawn_through_the_wall_ends_the_session_as_a_perforation) {
  // At the left tubal orifice, where the wall is about a centimetre thick.
  const WallSpot f("tubal-orifice-left");
  const auto wall = f.gauge->measure(f.world, f.sheet(0.001));
  ASSERT_TRUE(wall);
  const SessionReport through = sweep_into_the_wall(f, wall->thickness + 0.003);
  EXPECT_EQ(through.end_reason, "perforation");
  const auto ended = std::find_if(through.events.begin(), through.events.end(),
                                  [](const auto& e) { return e.kind == "perforation"; });
  ASSERT_NE(ended, through.events.end());
  EXPECT_NE(ended->message.find("the loop cut through the wall"), std::string::npos)
      << ended->message;  // the loop's sweep, not the sheath pressed through it
  ASSERT_TRUE(through.cutting.has_value());
  ASSERT_TRUE(through.cutting->deepest_wall_cut.has_value());
  EXPECT_DOUBLE_EQ(*through.cutting->deepest_wall_cut,
                   *through.cutting->wall_thickness_at_deepest_cut);
}

TEST(WallCutDepth,
     a_loop_drawn_two_millimetres_into_the_fundus_is_reported_and_the_session_goes_on) {
  const SessionReport shallow = sweep_into_the_wall(WallSpot("fundus"), 0.002);
  EXPECT_EQ(shallow.end_reason, "duration");
  ASSERT_TRUE(shallow.cutting->deepest_wall_cut.has_value());
  // Drawn straight across the fundus's bowl, the loop is 2 mm deep where it starts and deeper
  // towards its ends and the end of its stroke, 6.5 mm to the side, where the wall has curved
  // towards the cavity (1.5–2.5 mm for a bowl of 1–1.5 cm radius).
  EXPECT_GT(*shallow.cutting->deepest_wall_cut, 0.002);
  EXPECT_LT(*shallow.cutting->deepest_wall_cut, 0.005);
  EXPECT_LT(*shallow.cutting->deepest_wall_cut,
            0.5 * *shallow.cutting->wall_thickness_at_deepest_cut);
  EXPECT_TRUE(std::any_of(shallow.events.begin(), shallow.events.end(),
                          [](const auto& e) { return e.kind == "wall-cut"; }));
}

}  // namespace
}  // namespace viscera::sim
