// Chips out through the cervix (issue 17 §3): after the loop scoops a chip off the polyp, the
// loop stood out behind it and drawn back with the pedals up holds it against the sheath; the
// chip follows the instrument and, drawn back to the internal os, leaves the patient. The
// report counts it retrieved, its volume stays resected, and the run replays.

#include "simulator/session/chip_retrieval.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "simulator/session/instrument_input.h"
#include "simulator/session/manual_control.h"
#include "simulator/session/session_runner.h"
#include "tests/support/operative_session.h"
#include "tests/support/polyp_scoop.h"

namespace viscera::sim {
namespace {

constexpr double kScoopEnd = 1.5;  // s, the scoop script's length

core::Vec3 centre_of(const World& world, const Chip& chip) {
  const auto x = world.state().range(world.state().positions, chip.body);
  core::Vec3 sum = core::Vec3::Zero();
  for (const int n : chip.nodes)
    sum += x[static_cast<std::size_t>(n)];
  return sum / static_cast<double>(chip.nodes.size());
}

/// m, the largest distance of a chip node from the chip's centre.
double extent_of(const World& world, const Chip& chip) {
  const auto x = world.state().range(world.state().positions, chip.body);
  const core::Vec3 centre = centre_of(world, chip);
  double extent = 0.0;
  for (const int n : chip.nodes)
    extent = std::max(extent, (x[static_cast<std::size_t>(n)] - centre).norm());
  return extent;
}

core::Vec3 lerp(const core::Vec3& a, const core::Vec3& b, double s) {
  return a + std::clamp(s, 0.0, 1.0) * (b - a);
}

struct RetrievalRun {
  SessionReport report;
  bool caught_during_scoop = false;
  double chip_volume = 0.0;         ///< m³, rest volume of the chip the loop went for
  double resected_before = 0.0;     ///< m³, the polyp's resected volume before the retrieval
  double farthest_from_loop = 0.0;  ///< m, chip centre to loop centre while carried
  double carried = 0.0;             ///< m the chip's centre travelled while held
  double tip_travel = 0.0;          ///< m the tip travelled meanwhile
  std::size_t chip_nodes = 0;       ///< nodes of the chip caught
  std::size_t held_nodes = 0;       ///< of them, held by the loop when caught
  double extent_caught = 0.0;       ///< m, the chip's extent (extent_of) when caught
  double extent_carried = 0.0;      ///< m, its largest extent while carried
  double polyp_mass_before = 0.0;   ///< kg
  double polyp_mass_after = 0.0;    ///< kg
  int everted_at_end = -1;
};

double body_mass(const World& world, int body) {
  const auto m = world.state().range(world.state().masses, body);
  double sum = 0.0;
  for (const double v : m)
    sum += v;
  return sum;
}

/// The scoop, then: the shaft turned to point from the os at the chip, the loop stood out 6 mm
/// with its tip 4 mm before the chip (0.3 s), drawn back into the sheath (0.2 s), and the
/// instrument withdrawn to 2 mm behind where it started (1.0 s).
RetrievalRun scoop_and_retrieve(const core::Scenario& scenario) {
  const auto scoop = ScriptedTrajectory::from_json(
      testing::scoop_script(testing::frame_of(scenario), 2.0e-3), "scoop", 30.0);
  HeadlessRunOptions options;
  options.duration = kScoopEnd + 1.6;
  options.instrument = &scoop;
  options.instrument_body = "uterus";
  SessionRunner runner(scenario, options);
  const World& world = runner.world();
  const int polyp = world.body_index("polyp-1");
  RetrievalRun r;
  while (world.time() < kScoopEnd - 0.5 * world.time_step())
    runner.step(scoop.state(world.steps() + 1, world.time()));
  const auto caught = [&] {
    const auto& events = runner.report().events;
    return std::any_of(events.begin(), events.end(),
                       [](const auto& e) { return e.kind == "chip-caught"; });
  };
  r.caught_during_scoop = caught();
  const auto& chips = runner.resection()->chips();
  if (chips.empty()) return r;
  const Chip chip = chips.front();
  r.chip_volume = chip.rest_volume;
  r.resected_before = testing::resection_of(runner.report(), "polyp-1").resected_volume;
  r.polyp_mass_before = body_mass(world, polyp);

  const InstrumentState entry = starting_pose(scenario, scenario.session.instrument.optics_angle);
  const InstrumentState scooped = scoop.state(world.steps(), world.time());
  const core::Vec3 target = centre_of(world, chip);
  InstrumentState pose = scooped;
  pose.axis = (target - entry.tip).normalized();
  pose.up = pose.axis.unitOrthogonal();
  const core::Vec3 before_chip = target - 0.004 * pose.axis;
  const core::Vec3 out = entry.tip - 0.002 * entry.axis.normalized();
  core::Vec3 held_from = core::Vec3::Zero(), tip_from = core::Vec3::Zero();
  while (!runner.finished()) {
    const double t = world.time() + world.time_step() - kScoopEnd;
    if (t < 0.3) {
      pose.tip = lerp(scooped.tip, before_chip, t / 0.3);
      pose.loop_extension = 0.006 * std::clamp(t / 0.3, 0.0, 1.0);
    } else if (t < 0.5) {
      pose.tip = before_chip;
      pose.loop_extension = 0.006 * (1.0 - std::clamp((t - 0.3) / 0.2, 0.0, 1.0));
    } else {
      pose.tip = lerp(before_chip, out, (t - 0.5) / 1.0);
      pose.loop_extension = 0.0;
    }
    runner.step(pose);
    if (runner.chip_retrieval()->holding()) {
      const auto& now = runner.resection()->chips();
      const auto it = std::find_if(now.begin(), now.end(),
                                   [&](const Chip& c) { return c.nodes == chip.nodes; });
      if (it == now.end()) continue;
      const core::Vec3 centre = centre_of(world, *it);
      if (held_from.isZero()) {
        held_from = centre, tip_from = pose.tip, r.extent_caught = extent_of(world, *it);
        r.chip_nodes = it->nodes.size();
        for (const auto& term : world.terms()) {
          const auto* grasp = dynamic_cast<const GraspTerm*>(term.get());
          if (grasp != nullptr && grasp->holding()) r.held_nodes = grasp->held().size();
        }
      }
      r.extent_carried = std::max(r.extent_carried, extent_of(world, *it));
      r.carried = std::max(r.carried, (centre - held_from).norm());
      r.tip_travel = std::max(r.tip_travel, (pose.tip - tip_from).norm());
      r.farthest_from_loop =
          std::max(r.farthest_from_loop, (centre - loop_pose(pose).position).norm());
    }
  }
  r.polyp_mass_after = body_mass(world, polyp);
  r.everted_at_end = world.everted_tets();
  r.report = runner.finish();
  return r;
}

TEST(ChipRetrieval, a_chip_hooked_with_the_loop_is_carried_out_through_the_cervix) {
  const core::Scenario scenario = testing::resectoscope_patient();
  const RetrievalRun r = scoop_and_retrieve(scenario);
  ASSERT_GT(r.chip_volume, 0.0) << "the scoop cuts a chip";
  // The cutting stroke, drawn back with the pedal down, does not catch its own chip.
  EXPECT_FALSE(r.caught_during_scoop);
  ASSERT_TRUE(r.report.cutting.has_value());
  const BodyResection& polyp = testing::resection_of(r.report, "polyp-1");
  EXPECT_EQ(polyp.chips_retrieved, 1);
  EXPECT_DOUBLE_EQ(polyp.retrieved_volume, r.chip_volume);
  // Taking the chip out does not undo its resection.
  EXPECT_NEAR(polyp.resected_volume, r.resected_before, 1e-15);
  // The chip rode with the loop: as far as the tip went, never far from the loop.
  EXPECT_GT(r.tip_travel, 0.005);
  EXPECT_GT(r.carried, 0.8 * r.tip_travel);
  EXPECT_LT(r.farthest_from_loop, 0.006);
  // The loop clamps the whole chip against the sheath: it rides whole, not drawn out by the
  // nodes the loop reached.
  EXPECT_EQ(r.held_nodes, r.chip_nodes);
  EXPECT_LT(r.extent_carried, 1.1 * r.extent_caught);
  // Its tissue left the polyp: the body lost the chip's mass (ρ = m / V of the chip's tets).
  EXPECT_LT(r.polyp_mass_after, r.polyp_mass_before);
  EXPECT_NEAR(r.polyp_mass_before - r.polyp_mass_after,
              r.polyp_mass_before * r.chip_volume / polyp.initial_volume,
              0.01 * r.polyp_mass_before * r.chip_volume / polyp.initial_volume);
  EXPECT_EQ(r.everted_at_end, 0);
  const auto& events = r.report.events;
  const auto caught = std::find_if(events.begin(), events.end(),
                                   [](const auto& e) { return e.kind == "chip-caught"; });
  const auto out = std::find_if(events.begin(), events.end(),
                                [](const auto& e) { return e.kind == "chip-retrieved"; });
  ASSERT_NE(caught, events.end());
  ASSERT_NE(out, events.end());
  EXPECT_LT(caught->time, out->time);
}

TEST(ChipRetrieval, the_retrieval_replays_to_the_same_state) {
  const core::Scenario scenario = testing::resectoscope_patient();
  const RetrievalRun a = scoop_and_retrieve(scenario), b = scoop_and_retrieve(scenario);
  EXPECT_EQ(a.report.final_state_hash, b.report.final_state_hash);
  EXPECT_EQ(a.report.checkpoints, b.report.checkpoints);
}

}  // namespace
}  // namespace viscera::sim
