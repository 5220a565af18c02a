// The agent-tissue lab end to end (issue 16 part 2, seed 003 §V): the cell sheet of
// `viscera new --template agent-tissue` is a body of the session's world, the probe of
// data/scripts/agent-tissue-palpate.json presses it, the lab's palpate task is detected, and
// the tissue's state changes — the same way in every run.

#include <gtest/gtest.h>

#include "simulator/session/headless_session.h"
#include "simulator/session/instrument_input.h"
#include "simulator/world/world.h"
#include "templates/template_catalog.h"
#include "tests/support/test_paths.h"

namespace viscera::templates {
namespace {

sim::SessionReport palpate(const core::Scenario& scenario) {
  const auto script = sim::ScriptedTrajectory::read(
      (testing::source_dir() / "data" / "scripts" / "agent-tissue-palpate.json").string());
  sim::HeadlessRunOptions options;
  options.duration = script.duration();
  options.instrument = &script;
  options.instrument_body = script.body();
  options.instrument_stiffness = script.stiffness();
  return sim::run_headless(scenario, options);
}

TEST(AgentLabSession, the_scripted_probe_completes_the_palpate_task_and_moves_the_cells) {
  const core::Scenario scenario = build_from_template("agent-tissue", {}, 1);
  const std::string at_rest = sim::World(scenario).state_hash();
  const sim::SessionReport report = palpate(scenario);
  const sim::TaskResult* press = nullptr;
  for (const auto& task : report.tasks)
    if (task.id == "press-tissue") press = &task;
  ASSERT_NE(press, nullptr);
  EXPECT_EQ(press->status, "completed") << press->note << " best " << press->best;
  EXPECT_GE(press->best, 0.1);  // the largest force while touching, N
  // The sheet is a body of the world: 40 × 30 cells, pressed out of its plane.
  ASSERT_EQ(report.bodies.size(), 1u);
  EXPECT_EQ(report.bodies[0].name, "tissue");
  EXPECT_EQ(report.bodies[0].nodes, 1200u);
  EXPECT_GT(report.max_displacement, 1e-3);
  EXPECT_NE(report.final_state_hash, at_rest);
  // Deterministic: the same session gives the same bytes.
  EXPECT_EQ(palpate(scenario).final_state_hash, report.final_state_hash);
}

}  // namespace
}  // namespace viscera::templates
