// The agent-tissue lab end to end (issue 16 part 2, issue 17 §4, seed 003 §V): the cell sheet
// of `viscera new --template agent-tissue` is a body of the session's world, the bare shaft of
// data/scripts/agent-tissue-palpate.json presses it and the lab's palpate task is detected; in
// data/scripts/agent-tissue-lab.json the grasper then pulls it (its links stretch) and the
// scissors cut the links their blades cross until the sheet is divided — the same way in every
// run.

#include <gtest/gtest.h>

#include <stdexcept>

#include "simulator/session/headless_session.h"
#include "simulator/session/instrument_input.h"
#include "simulator/world/world.h"
#include "templates/template_catalog.h"
#include "tests/support/test_paths.h"

namespace viscera::templates {
namespace {

sim::SessionReport run_script(const core::Scenario& scenario, const std::string& name) {
  const auto script =
      sim::ScriptedTrajectory::read((testing::source_dir() / "data" / "scripts" / name).string());
  sim::HeadlessRunOptions options;
  options.duration = script.duration();
  options.instrument = &script;
  options.instrument_body = script.body();
  options.instrument_stiffness = script.stiffness();
  return sim::run_headless(scenario, options);
}

sim::SessionReport palpate(const core::Scenario& scenario) {
  return run_script(scenario, "agent-tissue-palpate.json");
}

const sim::TaskResult& task(const sim::SessionReport& report, const std::string& id) {
  for (const auto& t : report.tasks)
    if (t.id == id) return t;
  throw std::runtime_error("no task " + id);
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

TEST(AgentLabSession, the_grasper_stretches_the_sheet_and_the_scissors_divide_it_by_its_links) {
  const core::Scenario scenario = build_from_template("agent-tissue", {}, 1);
  const sim::SessionReport lab = run_script(scenario, "agent-tissue-lab.json");
  // Every task of the lab is simulated now: palpate, pull and cut.
  for (const auto& t : lab.tasks)
    EXPECT_EQ(t.status, "completed") << t.id << ": " << t.note << " best " << t.best;
  EXPECT_EQ(lab.end_reason, "completed");
  ASSERT_TRUE(lab.score.has_value());
  // The pull: the links at the grasped cells stretched past 20 % (the task's best).
  EXPECT_GE(task(lab, "pull-tissue").best, 0.2);
  ASSERT_TRUE(lab.laparoscopy.has_value());
  EXPECT_EQ(lab.laparoscopy->grasps, 1);
  // The sheet had come to rest after the palpation and the world slept; the jaws close 10 mm
  // below the proxy, which touches nothing, yet the held cells follow them: the jaws' springs
  // (30 N/m per knot) hardly stretch.
  EXPECT_LT(lab.laparoscopy->max_grasp_force, 0.5);
  // The cut: two closings of the blades across the links between columns 20 and 21, one per
  // row of the 30 — the first leaves the sheet whole, the second divides it.
  const auto& cuts = lab.laparoscopy->cuts;
  ASSERT_EQ(cuts.size(), 2u);
  int links = 0;
  for (const auto& c : cuts) {
    EXPECT_EQ(c.tool, "scissors");
    EXPECT_EQ(c.body, "tissue");
    EXPECT_EQ(c.tets_traversed, 0);
    links += c.links_removed;
  }
  EXPECT_EQ(links, 30);
  EXPECT_FALSE(cuts[0].separated());
  EXPECT_EQ(cuts[1].pieces_before, 1);
  EXPECT_EQ(cuts[1].pieces_after, 2);
  EXPECT_EQ(run_script(scenario, "agent-tissue-lab.json").final_state_hash, lab.final_state_hash);
}

}  // namespace
}  // namespace viscera::templates
