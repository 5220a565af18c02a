// Arterial bleeding and clips (issue 19 §2): the left uterine artery of the laparoscopy-gyn
// patient alone, with its pulsing vessel tree; scissors cut it across the middle of its distal
// segment, then a clip goes on either between the root and the cut (stops the bleeding) or
// beyond the cut (does not); either clip stops the pulse wave where it sits.

#include <gtest/gtest.h>

#include <algorithm>

#include "simulator/session/headless_session.h"
#include "simulator/session/instrument_input.h"
#include "tests/support/object_alone.h"

namespace viscera::sim {
namespace {

const core::Scenario& artery_patient() {
  static const core::Scenario s = testing::object_alone("laparoscopy-gyn", "artery-uterine-left");
  return s;
}

/// The jaws across the vessel at `point` (m): the shaft along +y into the body, the vessel
/// 5 mm behind the tip, the jaws closing across the vessel's direction `along`.
InstrumentState jaws_at(const core::Vec3& point, const core::Vec3& along, LaparoscopicTool tool,
                        bool closed) {
  InstrumentState s;
  s.axis = core::Vec3::UnitY();
  s.up = along.cross(s.axis).normalized();
  s.tip = point + 0.005 * s.axis;
  s.tool = tool;
  s.jaws_closed = closed;
  return s;
}

/// jaws_at, kept on the artery where it is now: the tip follows the displacement of the
/// artery's knots nearest `point` (its rest position), as a trainee's hand follows what he sees.
InstrumentState jaws_on_artery(const core::Vec3& point, const core::Vec3& along,
                               LaparoscopicTool tool, bool closed) {
  InstrumentState s = jaws_at(point, along, tool, closed);
  s.follow = 1.0;
  s.anchor = point;
  s.anchor_body = "artery-uterine-left";
  return s;
}

/// Cuts the distal segment at its middle at 0.3 s, then clips at `clip` (m, rest) at 0.7 s.
SessionReport cut_then_clip(const core::Vec3& clip, const core::Vec3& clip_along) {
  const core::VesselTree& tree = artery_patient().vessel_trees.at(0);
  const auto& distal = tree.segments.at(1);
  const core::Vec3 along = (distal.distal - distal.proximal).normalized();
  const core::Vec3 cut = 0.5 * (distal.proximal + distal.distal);
  InstrumentState away =
      jaws_at(cut - 0.03 * core::Vec3::UnitY(), along, LaparoscopicTool::None, false);
  const RecordedInput input(
      {{0, away},
       {100, jaws_at(cut, along, LaparoscopicTool::Scissors, false)},
       {300, jaws_at(cut, along, LaparoscopicTool::Scissors, true)},
       {400, jaws_at(cut, along, LaparoscopicTool::Scissors, false)},
       {500, jaws_on_artery(clip, clip_along, LaparoscopicTool::ClipApplier, false)},
       {700, jaws_on_artery(clip, clip_along, LaparoscopicTool::ClipApplier, true)},
       {800, jaws_on_artery(clip, clip_along, LaparoscopicTool::ClipApplier, false)},
       {900, away}});
  HeadlessRunOptions options;
  options.duration = 1.5;
  options.instrument = &input;
  options.instrument_body = "artery-uterine-left";
  options.end_when_complete = false;
  return run_headless(artery_patient(), options);
}

/// The session's events, one a line, for failure messages.
std::string event_lines(const SessionReport& r) {
  std::string text;
  for (const auto& e : r.events)
    text += std::to_string(e.time) + " " + e.kind + ": " + e.message + "\n";
  return text;
}

/// The opened artery's source, or null (with the session's events in the failure message).
const fluid::BleedingSource* artery_source(const SessionReport& r) {
  const auto& sources = *r.bleeding;
  const auto it =
      std::find_if(sources.begin(), sources.end(), [](const auto& s) { return !s.capillary; });
  if (it != sources.end()) return &*it;
  ADD_FAILURE() << "no artery opened; " << sources.size() << " source(s)\n" << event_lines(r);
  return nullptr;
}

int events(const SessionReport& r, const std::string& kind) {
  return static_cast<int>(std::count_if(r.events.begin(), r.events.end(),
                                        [&](const auto& e) { return e.kind == kind; }));
}

TEST(ArterialClip, a_clip_between_the_root_and_the_cut_stops_the_bleeding_one_beyond_it_does_not) {
  const core::VesselTree& tree = artery_patient().vessel_trees.at(0);
  ASSERT_EQ(tree.segments.size(), 2u);
  const auto& root = tree.segments[0];
  const auto& distal = tree.segments[1];
  const core::Vec3 root_along = (root.distal - root.proximal).normalized();
  const core::Vec3 distal_along = (distal.distal - distal.proximal).normalized();

  const SessionReport right = cut_then_clip(0.5 * (root.proximal + root.distal), root_along);
  ASSERT_TRUE(right.bleeding.has_value());
  ASSERT_EQ(right.laparoscopy->cuts.size(), 1u);
  ASSERT_EQ(right.laparoscopy->clips.size(), 1u) << event_lines(right);
  const fluid::BleedingSource* opened = artery_source(right);
  ASSERT_NE(opened, nullptr);
  const fluid::BleedingSource& stopped = *opened;
  EXPECT_EQ(stopped.segment, 1);
  EXPECT_EQ(stopped.stop, fluid::BleedingStop::Clipped);
  EXPECT_NEAR(stopped.stopped_at, 0.7, 0.002);
  EXPECT_GT(stopped.bled, 0.0);  // it bled for 0.4 s between the cut and the clip
  // It spurts in time with the pulse: the pressure behind it swings with the heart rate.
  EXPECT_NEAR(stopped.pulse_period, 60.0 / 72.0, 1e-12);
  EXPECT_GT(stopped.pulse_delay, 0.0);
  EXPECT_GT(stopped.pulse_amplitude, 0.2);
  EXPECT_EQ(events(right, "bleeding-clipped"), 1);
  EXPECT_GE(events(right, "pulse-stopped"), 1);

  const SessionReport wrong =
      cut_then_clip(distal.proximal + 0.8 * (distal.distal - distal.proximal), distal_along);
  ASSERT_EQ(wrong.laparoscopy->clips.size(), 1u) << event_lines(wrong);
  const fluid::BleedingSource* open = artery_source(wrong);
  ASSERT_NE(open, nullptr);
  const fluid::BleedingSource& still = *open;
  EXPECT_EQ(still.stop, fluid::BleedingStop::Bleeding);
  EXPECT_GT(still.bled, stopped.bled);
  EXPECT_EQ(events(wrong, "bleeding-clipped"), 0);
}

}  // namespace
}  // namespace viscera::sim
