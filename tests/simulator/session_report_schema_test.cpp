// report.json against its published schema (docs/session-report.schema.json): the reports of
// real sessions validate, and a report missing a metric or with an unknown end is caught.

#include <gtest/gtest.h>

#include <fstream>

#include "core/json_schema/json_schema_validator.h"
#include "simulator/session/headless_session.h"
#include "tests/simulator/session_fixtures.h"
#include "tests/support/test_paths.h"

namespace viscera::sim {
namespace {

core::JsonSchemaValidator report_schema() {
  std::ifstream in(viscera::testing::source_dir() / "docs" / "session-report.schema.json");
  return core::JsonSchemaValidator(nlohmann::json::parse(in));
}

nlohmann::json scripted_report(const nlohmann::json& script) {
  const core::Scenario scenario = viscera::testing::cavity_scenario();
  const auto input = ScriptedTrajectory::from_json(script, "script");
  HeadlessRunOptions options;
  options.duration = input.duration() + 1.0;
  options.instrument = &input;
  options.instrument_body = "uterus";
  return report_to_json(run_headless(scenario, options));
}

std::string describe(const std::vector<core::SchemaViolation>& violations) {
  std::string out;
  for (const auto& v : violations)
    out += v.pointer + ": " + v.message + "\n";
  return out;
}

TEST(SessionReportSchema, expert_and_novice_reports_validate) {
  const auto schema = report_schema();
  for (const auto& script :
       {viscera::testing::expert_cavity_script(), viscera::testing::novice_cavity_script()}) {
    const nlohmann::json report = scripted_report(script);
    ASSERT_FALSE(report["procedure_steps"].empty());
    ASSERT_FALSE(report["path"]["tip"].empty());
    const auto violations = schema.validate(report);
    EXPECT_TRUE(violations.empty()) << describe(violations);
  }
}

TEST(SessionReportSchema, catches_a_missing_metric_and_an_unknown_end) {
  const auto schema = report_schema();
  nlohmann::json report = scripted_report(viscera::testing::expert_cavity_script());
  report["metrics"].erase("max_force");
  report["end_reason"] = "lunch";
  const auto violations = schema.validate(report);
  const std::string text = describe(violations);
  EXPECT_NE(text.find("/metrics"), std::string::npos) << text;
  EXPECT_NE(text.find("/end_reason"), std::string::npos) << text;
}

TEST(SessionReportSchema, an_unassessed_session_has_a_null_score_with_its_reason) {
  const auto schema = report_schema();
  const core::Scenario scenario = viscera::testing::cavity_scenario();
  HeadlessRunOptions options;
  options.duration = 0.1;  // no instrument: nothing of a trainee's work to assess
  const nlohmann::json report = report_to_json(run_headless(scenario, options));
  EXPECT_TRUE(report["score"].is_null());
  ASSERT_TRUE(report["score_reason"].is_string());
  EXPECT_FALSE(report["score_reason"].get<std::string>().empty());
  const auto violations = schema.validate(report);
  EXPECT_TRUE(violations.empty()) << describe(violations);
  // A null score without its reason is caught.
  nlohmann::json silent = report;
  silent["score_reason"] = 3;
  silent["score"] = -1;
  const std::string text = describe(schema.validate(silent));
  EXPECT_NE(text.find("/score_reason"), std::string::npos) << text;
  EXPECT_NE(text.find("/score"), std::string::npos) << text;
}

}  // namespace
}  // namespace viscera::sim
