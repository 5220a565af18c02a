// Sessions in the urethra lattice (issue 8 item 2, seed 002 §3, §5): the SessionRunner drives the
// seed-002 force model from the scripted endoscope. The shipped expert completes the insertion
// below the warning level; the novice meets higher forces and warnings; a forced push past the
// break force ends the session; recorded sessions replay hash for hash.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "core/error.h"
#include "core/scenario/procedure.h"
#include "simulator/session/headless_session.h"
#include "simulator/session/instrument_input.h"
#include "simulator/session/urethra_tissue.h"
#include "tests/support/test_paths.h"

namespace viscera::sim {
namespace {

/// The urethra template's patient at its defaults: lattice, landmarks and the embedded
/// insertion procedure.
core::Scenario urethra_scenario() {
  core::Scenario scenario;
  core::UrethraLatticeSpec spec;
  spec.object = "urethra";
  scenario.urethra_lattices.push_back(spec);
  const double a = spec.curvature, L = spec.length;
  scenario.landmarks.push_back({"urethral-meatus", "External urethral meatus", "urethra",
                                core::Vec3::Zero(), -core::Vec3::UnitZ()});
  scenario.landmarks.push_back({"bladder-entrance", "Bladder entrance", "urethra",
                                core::Vec3(0.0, a * L * L, L),
                                core::Vec3(0.0, 2.0 * a * L, 1.0).normalized()});
  scenario.session.gravity = core::Vec3::Zero();
  core::apply_procedure(scenario.session,
                        core::procedure_definition("urethral-endoscope-insertion"));
  return scenario;
}

ScriptedTrajectory shipped(const core::Scenario& scenario, const std::string& name) {
  const auto path = testing::source_dir() / "data" / "scripts" / (name + ".json");
  std::ifstream in(path);
  const nlohmann::json resolved =
      resolve_script_landmarks(nlohmann::json::parse(in), scenario.landmarks, path.string());
  return ScriptedTrajectory::from_json(resolved, path.string(),
                                       scenario.session.instrument.optics_angle);
}

SessionReport run(const core::Scenario& scenario, const InstrumentInput& input, double duration,
                  const std::string& body = "urethra") {
  HeadlessRunOptions options;
  options.duration = duration;
  options.instrument = &input;
  options.instrument_body = body;
  options.record_inputs = true;
  return run_headless(scenario, options);
}

int count(const SessionReport& report, const std::string& kind) {
  return static_cast<int>(std::count_if(report.events.begin(), report.events.end(),
                                        [&](const SessionEvent& e) { return e.kind == kind; }));
}

TEST(UrethraSession, expert_completes_the_insertion_below_the_warning_level) {
  const core::Scenario scenario = urethra_scenario();
  const ScriptedTrajectory expert = shipped(scenario, "urethra-expert");
  const SessionReport report = run(scenario, expert, expert.duration() + 1.0);
  EXPECT_EQ(report.end_reason, "completed");
  for (const auto& task : report.tasks)
    EXPECT_EQ(task.status, "completed") << task.id;
  EXPECT_EQ(report.metrics.tasks_completed(), 4);
  // The endoscope, wider than the lumen, stretches the wall the whole way: one touch.
  EXPECT_EQ(report.metrics.contacts(), 1);
  EXPECT_GT(report.metrics.max_force(), 0.5);
  EXPECT_LT(report.metrics.max_force(), scenario.session.force_warning);
  EXPECT_EQ(count(report, "force-warning"), 0);
  EXPECT_EQ(count(report, "excessive-force"), 0);
}

TEST(UrethraSession, novice_meets_higher_forces_and_warnings) {
  const core::Scenario scenario = urethra_scenario();
  const ScriptedTrajectory expert = shipped(scenario, "urethra-expert");
  const ScriptedTrajectory novice = shipped(scenario, "urethra-novice");
  const SessionReport e = run(scenario, expert, expert.duration() + 1.0);
  const SessionReport n = run(scenario, novice, novice.duration() + 1.0);
  EXPECT_NE(n.end_reason, "perforation");
  EXPECT_NE(n.end_reason, "tissue-tear");
  EXPECT_GT(n.metrics.max_force(), e.metrics.max_force() + 0.3);
  EXPECT_GT(count(n, "force-warning"), count(e, "force-warning"));
  EXPECT_GT(count(n, "excessive-force"), 0);
  EXPECT_NE(n.final_state_hash, e.final_state_hash);
}

TEST(UrethraSession, a_push_past_the_break_force_perforates_and_ends_the_session) {
  const core::Scenario scenario = urethra_scenario();
  // 2 m/s deep in the urethra: Coulomb friction plus 4 N of viscous drag exceed the 4 N limit.
  const double a = 13.0;
  const auto on_line = [&](double z) { return core::Vec3(0.0, a * z * z, z); };
  // Rests at z = 0.10 m first; then it moves 2 mm per 1 ms step.
  std::vector<std::pair<long long, InstrumentState>> changes;
  for (long long s = 0; s <= 40; ++s) {
    const double z = 0.10 + (s > 10 ? 0.002 * static_cast<double>(s - 10) : 0.0);
    changes.emplace_back(
        s, InstrumentState{on_line(z), core::Vec3(0.0, 2.0 * a * z, 1.0).normalized()});
  }
  const RecordedInput forced(changes);
  const SessionReport report = run(scenario, forced, 1.0);
  EXPECT_EQ(report.end_reason, "perforation");
  EXPECT_LT(report.simulated_time, 0.02);
  EXPECT_GT(report.simulated_time, 0.01);
  EXPECT_EQ(count(report, "perforation"), 1);
  EXPECT_GE(report.metrics.max_force(), 4.0 * 0.999);
}

TEST(UrethraSession, replays_bit_identically_from_the_recorded_inputs) {
  const core::Scenario scenario = urethra_scenario();
  const ScriptedTrajectory novice = shipped(scenario, "urethra-novice");
  const SessionReport first = run(scenario, novice, novice.duration());
  ASSERT_FALSE(first.checkpoints.empty());
  const RecordedInput recorded(first.inputs);
  const SessionReport again = run(scenario, recorded, novice.duration());
  EXPECT_EQ(again.checkpoints, first.checkpoints);
  EXPECT_EQ(again.final_state_hash, first.final_state_hash);
  EXPECT_EQ(again.metrics.max_force(), first.metrics.max_force());
  EXPECT_EQ(again.events.size(), first.events.size());
}

TEST(UrethraSession, an_unknown_instrument_body_is_an_input_error) {
  const core::Scenario scenario = urethra_scenario();
  const RecordedInput still({{0, InstrumentState{}}});
  EXPECT_THROW(run(scenario, still, 0.1, "bladder"), core::InputError);
}

TEST(UrethraTissue, maps_the_pose_to_the_endoscope_state_of_the_force_model) {
  const core::UrethraLatticeSpec spec;
  const double z = 0.08, pitch = std::atan(2.0 * spec.curvature * z);
  InstrumentState at;
  at.tip = core::Vec3(0.0, spec.curvature * z * z, z);
  at.axis = core::Vec3(0.0, std::sin(pitch), std::cos(pitch));
  at.up = core::Vec3(0.0, std::cos(pitch), -std::sin(pitch));
  UrethraTissue tissue(spec, at);
  EXPECT_NEAR(tissue.endoscope().pitch, pitch, 1e-12);
  EXPECT_NEAR(tissue.endoscope().yaw, 0.0, 1e-12);
  EXPECT_TRUE(tissue.in_contact());  // the 4 mm scope in the 1 mm lumen stretches the wall
  const std::string rest = tissue.state_hash();

  // 0.5 mm along the axis and a 0.01 rad roll about it in 1 ms: 0.5 m/s and 10 rad/s.
  InstrumentState next = at;
  next.tip += 0.0005 * at.axis;
  next.up = std::cos(0.01) * at.up + std::sin(0.01) * at.axis.cross(at.up);
  tissue.move(next, 0.001);
  EXPECT_NEAR(tissue.endoscope().velocity.dot(at.axis), 0.5, 1e-9);
  EXPECT_NEAR(tissue.endoscope().spin_rate, 10.0, 1e-6);
  // Friction and the sloping wall resist the insertion; the roll meets a torque about the axis.
  EXPECT_LT(tissue.force().dot(at.axis), 0.0);
  EXPECT_TRUE(tissue.force().isApprox(tissue.feedback().force));
  EXPECT_LT(tissue.feedback().torque_z, 0.0);
  EXPECT_NE(tissue.state_hash(), rest);

  // Turned out of the plane of symmetry: yaw from the axis' x component.
  next.axis =
      core::Vec3(std::sin(0.1) * std::cos(pitch), std::sin(pitch), std::cos(0.1) * std::cos(pitch));
  tissue.move(next, 0.001);
  EXPECT_NEAR(tissue.endoscope().yaw, 0.1, 1e-9);
  EXPECT_LT(tissue.feedback().torque_y, 0.0);
}

}  // namespace
}  // namespace viscera::sim
