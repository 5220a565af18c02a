#include "core/scenario/procedure.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/package/scenario_package.h"
#include "core/scenario/scenario_json.h"
#include "tests/core/scenario_fixtures.h"
#include "tests/support/test_paths.h"

namespace viscera::core {
namespace {

TEST(Procedure, ships_the_procedures_of_issues_8_and_17) {
  EXPECT_EQ(procedure_definition_names(),
            (std::vector<std::string>{"agent-tissue-lab", "diagnostic-hysteroscopy",
                                      "hysteroscopic-myomectomy", "hysteroscopic-polypectomy",
                                      "laparoscopic-tubal-sterilisation",
                                      "urethral-endoscope-insertion"}));
  const ProcedureDefinition& hysteroscopy = procedure_definition("diagnostic-hysteroscopy");
  EXPECT_EQ(hysteroscopy.procedure, "hysteroscopy");
  EXPECT_EQ(hysteroscopy.instrument.kind, "hysteroscope");
  EXPECT_EQ(hysteroscopy.instrument.optics_angle, 30.0);
  ASSERT_EQ(hysteroscopy.steps.size(), 3u);
  EXPECT_EQ(hysteroscopy.steps[0].id, "insert");
  EXPECT_EQ(hysteroscopy.steps[1].id, "inspect");
  EXPECT_EQ(hysteroscopy.steps[2].id, "withdraw");
  // Inspect: a panoramic view and one substep per tubal orifice, each centring its landmark.
  ASSERT_EQ(hysteroscopy.steps[1].substeps.size(), 3u);
  EXPECT_EQ(hysteroscopy.steps[1].substeps[1].tasks[0].kind, "centre-target");
  EXPECT_EQ(hysteroscopy.steps[1].substeps[1].tasks[0].parameters["landmark"],
            "tubal-orifice-right");
  EXPECT_EQ(hysteroscopy.steps[1].substeps[2].tasks[0].parameters["landmark"],
            "tubal-orifice-left");
  // Sterilisation: grasp, coagulate, clip twice, cut.
  const ProcedureDefinition& sterilisation =
      procedure_definition("laparoscopic-tubal-sterilisation");
  std::vector<std::string> kinds;
  SessionSpec session;
  apply_procedure(session, sterilisation);
  for (const TaskSpec* task : all_tasks(session))
    kinds.push_back(task->kind);
  EXPECT_EQ(kinds, (std::vector<std::string>{"centre-target", "centre-target", "grasp", "coagulate",
                                             "clip", "clip", "cut"}));
  EXPECT_THROW(procedure_definition("appendectomy"), UsageError);
}

TEST(Procedure, round_trips_through_json_and_names_bad_members) {
  for (const auto& name : procedure_definition_names()) {
    const ProcedureDefinition& p = procedure_definition(name);
    EXPECT_EQ(procedure_from_json(nlohmann::json::parse(procedure_to_json(p).dump()), "p.json"), p)
        << name;
  }
  nlohmann::json broken = procedure_to_json(procedure_definition("diagnostic-hysteroscopy"));
  broken["steps"][1]["substeps"][2]["tasks"][0]["id"] = "inspect-cavity";
  try {
    procedure_from_json(broken, "p.json");
    FAIL() << "duplicate task id accepted";
  } catch (const ValidationError& e) {
    EXPECT_NE(std::string(e.what()).find("p.json: /steps/1/substeps/2/tasks/0/id"),
              std::string::npos)
        << e.what();
  }
  broken = procedure_to_json(procedure_definition("agent-tissue-lab"));
  broken["steps"][0]["substeps"] = nlohmann::json::array();
  EXPECT_THROW(procedure_from_json(broken, "p.json"), ValidationError);
  broken = procedure_to_json(procedure_definition("agent-tissue-lab"));
  broken["procedure"] = "dentistry";
  EXPECT_THROW(procedure_from_json(broken, "p.json"), ValidationError);
}

TEST(Procedure, embedded_in_a_scenario_round_trips_through_a_package_and_its_schema) {
  Scenario scenario = viscera::testing::full_scenario();
  apply_procedure(scenario.session, procedure_definition("diagnostic-hysteroscopy"));
  scenario.session.force_warning = 1.25;
  const nlohmann::json json = scenario_to_json(scenario);
  const Scenario back = scenario_from_json(json, "m.json");
  EXPECT_EQ(back.session, scenario.session);
  // Written and read as a package: the manifest passes the package schema (read_package
  // validates it) and the procedure comes back equal.
  const auto path = viscera::testing::scratch_dir() / "procedure.vscene";
  write_package(scenario, path);
  EXPECT_EQ(read_package(path).session, scenario.session);
  // A scenario without steps writes no procedure members, so older manifests stay as they were.
  EXPECT_FALSE(scenario_to_json(viscera::testing::full_scenario())["session"].contains("steps"));
}

}  // namespace
}  // namespace viscera::core
