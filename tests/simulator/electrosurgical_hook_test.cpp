// The monopolar L-hook (issue 17 §4): its wire's sweep under cutting current divides the left
// uterine artery of a laparoscopy-gyn patient (alone, as in the arterial clip test) and opens
// it; the same stroke without current cuts nothing; coagulating current on the artery coagulates
// the knots the wire touches and raises smoke.

#include "simulator/session/electrosurgical_hook.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "core/error.h"
#include "simulator/cutting/cut_surface.h"
#include "simulator/session/headless_session.h"
#include "simulator/session/instrument_input.h"
#include "tests/support/object_alone.h"

namespace viscera::sim {
namespace {

const core::Scenario& artery_patient() {
  // Vessels of 1.5 mm radius (the template's lowest): the hook's 4 mm arm reaches across.
  static const core::Scenario s = testing::object_alone("laparoscopy-gyn", "artery-uterine-left",
                                                        {{"vessel_radius", "0.0015"}});
  return s;
}

/// The vessel's distal segment (0.7 of the main vessel's radius): the hook works across its
/// middle.
const core::VesselSegment& segment() {
  return artery_patient().vessel_trees.at(0).segments.at(1);
}

/// The hook with the shaft along +y, its arm across the vessel (along `up` ⟂ the vessel and the
/// shaft), the bend `depth` m beyond the vessel's axis along the shaft and `below` m under it
/// along the arm: the arm reaches from there to 4 mm above.
InstrumentState hook_at(double depth, double below, bool cutting, bool coagulating) {
  const core::Vec3 centre = 0.5 * (segment().proximal + segment().distal);
  const core::Vec3 along = (segment().distal - segment().proximal).normalized();
  InstrumentState s;
  s.tool = LaparoscopicTool::Hook;
  s.axis = core::Vec3::UnitY();
  s.up = along.cross(s.axis).normalized();
  s.tip = centre + depth * s.axis - below * s.up;
  s.electrode = cutting;
  s.coagulation = coagulating;
  return s;
}

/// In from 3 cm in front beside the vessel, behind it; then drawn back across it through
/// `steps` steps (with cutting current when `cutting`), and out.
SessionReport stroke(bool cutting) {
  const double r = segment().radius;
  const double below = r + 0.2e-3;
  std::vector<std::pair<long long, InstrumentState>> changes;
  changes.emplace_back(0, hook_at(-0.03, below, false, false));
  changes.emplace_back(100, hook_at(r + 2e-3, below, false, false));
  // Drawn back 0.1 mm per step from behind the vessel to in front of it.
  const int steps = static_cast<int>((2.0 * r + 4e-3) / 1e-4);
  for (int k = 0; k <= steps; ++k)
    changes.emplace_back(200 + k, hook_at(r + 2e-3 - 1e-4 * k, below, cutting, false));
  changes.emplace_back(201 + steps, hook_at(-r - 2e-3, below, false, false));
  changes.emplace_back(300 + steps, hook_at(-0.03, below, false, false));
  const RecordedInput input(std::move(changes));
  HeadlessRunOptions options;
  options.duration = 0.5 + steps * 1e-3;
  options.instrument = &input;
  options.instrument_body = "artery-uterine-left";
  options.end_when_complete = false;
  return run_headless(artery_patient(), options);
}

TEST(ElectrosurgicalHook, the_wire_is_an_L_from_the_bare_shank_through_the_bend_along_up) {
  InstrumentState s;
  s.tip = core::Vec3(0.01, 0.0, 0.0);
  s.axis = core::Vec3::UnitZ();
  s.up = core::Vec3::UnitY();
  const HookOptions options;
  const auto wire = hook_wire(s, options);
  EXPECT_TRUE(wire[0].isApprox(s.tip - options.shank * s.axis));
  EXPECT_TRUE(wire[1].isApprox(s.tip));
  EXPECT_TRUE(wire[2].isApprox(s.tip + options.length * s.up));
  EXPECT_NEAR(distance_to_hook(s.tip + 0.002 * s.up + 0.001 * core::Vec3::UnitX(), s, options),
              0.001, 1e-12);
  // The bend touches; under cutting current the insulated shaft behind the bare wire does.
  EXPECT_TRUE(hook_touch_point(s, options).isApprox(s.tip));
  s.electrode = true;
  EXPECT_TRUE(hook_touch_point(s, options).isApprox(wire[0]));
}

TEST(ElectrosurgicalHook, a_sweep_is_cut_when_the_current_stops_and_only_if_the_wire_moved) {
  HookSweep sweep;
  InstrumentState s;
  s.tool = LaparoscopicTool::Hook;
  s.up = core::Vec3::UnitY();
  s.electrode = true;
  EXPECT_FALSE(sweep.follow(s));  // the current flows, the wire stands still
  EXPECT_TRUE(sweep.recording());
  s.electrode = false;
  EXPECT_FALSE(sweep.follow(s));  // released without moving: nothing swept
  EXPECT_FALSE(sweep.recording());
  s.electrode = true;
  for (int k = 0; k <= 30; ++k) {
    s.tip = core::Vec3(0.0, 0.0, -1e-4 * k);
    EXPECT_FALSE(sweep.follow(s));
  }
  s.tool = LaparoscopicTool::Grasper;  // taken out of the port with the pedal still down
  const auto surface = sweep.follow(s);
  ASSERT_TRUE(surface.has_value());
  // The L drawn back 3 mm along its shaft: the arm sweeps 4 mm × 3 mm, the shank lies in line.
  double area = 0.0;
  for (const auto& t : surface->triangles)
    area += 0.5 * (surface->vertices[t[1]] - surface->vertices[t[0]])
                      .cross(surface->vertices[t[2]] - surface->vertices[t[0]])
                      .norm();
  EXPECT_NEAR(area, 0.004 * 0.003, 1e-9);
}

TEST(ElectrosurgicalHook, a_stroke_with_cutting_current_divides_the_artery_and_opens_it) {
  ASSERT_LT(2.0 * segment().radius, HookOptions{}.length) << "the arm must reach across the vessel";
  const SessionReport cut = stroke(true);
  ASSERT_TRUE(cut.laparoscopy.has_value());
  ASSERT_EQ(cut.laparoscopy->cuts.size(), 1u);
  const TissueCut& c = cut.laparoscopy->cuts[0];
  EXPECT_EQ(c.tool, "hook");
  EXPECT_EQ(c.body, "artery-uterine-left");
  EXPECT_TRUE(c.separated());
  ASSERT_TRUE(cut.bleeding.has_value());
  EXPECT_TRUE(std::any_of(cut.bleeding->begin(), cut.bleeding->end(),
                          [](const auto& s) { return !s.capillary && s.bled > 0.0; }));
  // The cutting current raises a plume where the wire vaporises the tissue.
  EXPECT_GT(cut.laparoscopy->smoke_puffs, 0);

  // The same stroke without current cuts nothing: the hook only pushes the vessel.
  const SessionReport cold = stroke(false);
  ASSERT_TRUE(cold.laparoscopy.has_value());
  EXPECT_TRUE(cold.laparoscopy->cuts.empty());
  EXPECT_EQ(cold.laparoscopy->smoke_puffs, 0);
}

TEST(ElectrosurgicalHook, coagulating_current_on_the_vessel_coagulates_what_the_wire_touches) {
  const double r = segment().radius;
  // The arm laid against the vessel's near side: the wire within reach of its surface knots.
  const RecordedInput input({{0, hook_at(-0.03, r + 0.2e-3, false, false)},
                             {100, hook_at(-r - 0.3e-3, r + 0.2e-3, false, false)},
                             {200, hook_at(-r - 0.3e-3, r + 0.2e-3, false, true)},
                             {1700, hook_at(-r - 0.3e-3, r + 0.2e-3, false, false)}});
  HeadlessRunOptions options;
  options.duration = 1.9;
  options.instrument = &input;
  options.instrument_body = "artery-uterine-left";
  options.end_when_complete = false;
  const SessionReport r1 = run_headless(artery_patient(), options);
  ASSERT_TRUE(r1.laparoscopy.has_value());
  EXPECT_NEAR(r1.laparoscopy->coagulation_time, 1.5, 0.01);
  ASSERT_EQ(r1.laparoscopy->coagulated.size(), 1u);
  EXPECT_EQ(r1.laparoscopy->coagulated[0].body, "artery-uterine-left");
  EXPECT_GT(r1.laparoscopy->coagulated[0].nodes, 0);
  EXPECT_GT(r1.laparoscopy->smoke_puffs, 0);
  EXPECT_TRUE(r1.laparoscopy->cuts.empty());
}

TEST(SweptWireSurface, bad_sweeps_are_refused_with_one_sentence) {
  using cutting::swept_wire_surface;
  const std::vector<core::Vec3> wire = {core::Vec3::Zero(), core::Vec3::UnitX()};
  EXPECT_THROW(swept_wire_surface({wire}), core::InputError);
  EXPECT_THROW(swept_wire_surface({wire, {core::Vec3::UnitY()}}), core::InputError);
  EXPECT_THROW(swept_wire_surface({wire, wire}), core::InputError);  // no area
  std::vector<core::Vec3> bad = wire;
  bad[1].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(swept_wire_surface({wire, bad}), core::InputError);
  const auto moved = swept_wire_surface({wire, {core::Vec3::UnitY(), core::Vec3(1, 1, 0)}});
  EXPECT_EQ(moved.triangles.size(), 2u);
}

}  // namespace
}  // namespace viscera::sim
