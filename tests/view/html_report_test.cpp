// The HTML report of real sessions: a novice's page set against the expert's report references
// only images that exist and are PNGs drawn by VTK's charts, and marks every comparable metric;
// fluid, bleeding and a resection get their tables.

#include "simulator/report/html_report.h"

#include <gtest/gtest.h>
#include <vtkImageData.h>

#include <fstream>
#include <sstream>
#include <tuple>

#include "core/error.h"
#include "simulator/session/headless_session.h"
#include "simulator/session/manual_control.h"
#include "simulator/view/scene_surfaces.h"
#include "tests/simulator/session_fixtures.h"
#include "tests/support/polyp_scoop.h"
#include "tests/support/test_paths.h"
#include "tests/view/view_fixtures.h"

namespace viscera::report {
namespace {

nlohmann::json scripted_report(
    const nlohmann::json& script,
    const core::Scenario& scenario = viscera::testing::cavity_scenario()) {
  const auto input = sim::ScriptedTrajectory::from_json(script, "script");
  sim::HeadlessRunOptions options;
  options.duration = input.duration() + 1.0;
  options.instrument = &input;
  options.instrument_body = "uterus";
  return sim::report_to_json(sim::run_headless(scenario, options));
}

TEST(MetricComparison, follows_the_direction_of_each_metric) {
  const auto find = [](const std::string& key) {
    for (const auto& m : report_metrics())
      if (m.key == key) return m;
    throw std::runtime_error(key);
  };
  EXPECT_EQ(compare_metric(find("path_length"), 0.1, 0.2), "better");
  EXPECT_EQ(compare_metric(find("path_length"), 0.3, 0.2), "worse");
  EXPECT_EQ(compare_metric(find("surface_seen"), 0.3, 0.2), "better");
  EXPECT_EQ(compare_metric(find("contacts"), 4, 4), "equal");
}

TEST(HtmlReport, novice_page_against_the_expert_references_existing_plots) {
  const nlohmann::json expert = scripted_report(viscera::testing::expert_cavity_script());
  const nlohmann::json novice = scripted_report(viscera::testing::novice_cavity_script());
  const auto dir = viscera::testing::scratch_dir();
  const auto written = write_html_report(novice, &expert, dir);
  ASSERT_EQ(written.front(), dir / "report.html");
  const std::string html = viscera::testing::file_bytes(dir / "report.html");
  const auto images = referenced_images(html);
  ASSERT_EQ(images.size(), 4u);
  for (const std::string& image : images) {
    SCOPED_TRACE(image);
    EXPECT_EQ(image.find('/'), std::string::npos) << "images sit beside the page";
    const std::string bytes = viscera::testing::file_bytes(dir / image);
    ASSERT_GT(bytes.size(), 2000u);
    const auto png = view::decode_png(bytes, image);
    int dims[3];
    png->GetDimensions(dims);
    EXPECT_EQ(dims[0], 820);
    EXPECT_EQ(dims[1], 480);
    // A chart, not a blank page: white background with drawn marks of several colours.
    const auto stats = viscera::testing::frame_statistics(png, 0.0);
    EXPECT_GT(stats.luminance_stddev, 10.0);
  }
  // The path plot colours samples by wall distance: red near the wall and blue far from it.
  const auto path =
      view::decode_png(viscera::testing::file_bytes(dir / "path_xy.png"), "path_xy.png");
  int red = 0, blue = 0;
  const auto* p = static_cast<const unsigned char*>(path->GetScalarPointer());
  const int channels = path->GetNumberOfScalarComponents();
  for (vtkIdType i = 0; i < path->GetNumberOfPoints(); ++i, p += channels) {
    if (p[0] > 180 && p[1] < 90 && p[2] < 90) ++red;
    if (p[2] > 180 && p[0] < 90) ++blue;
  }
  EXPECT_GT(red, 20);
  EXPECT_GT(blue, 20);
  // Every metric with values on both sides is judged; the novice loses on collisions.
  EXPECT_NE(html.find("<td>Tool-wall collisions</td>"), std::string::npos);
  const std::size_t row = html.find("Tool-wall collisions");
  ASSERT_NE(row, std::string::npos);
  const std::string collisions = html.substr(row, html.find("</tr>", row) - row);
  EXPECT_NE(collisions.find("class=\"worse\""), std::string::npos) << collisions;
  EXPECT_NE(html.find("Reference score"), std::string::npos);
}

TEST(HtmlReport, an_unassessed_session_says_so_instead_of_a_score) {
  // The expert's patient with the instrument resting where the session starts: never moved.
  const core::Scenario scenario = viscera::testing::cavity_scenario();
  const sim::RecordedInput resting({{0, sim::starting_pose(scenario, 30.0)}});
  sim::HeadlessRunOptions options;
  options.duration = 0.3;
  options.instrument = &resting;
  options.instrument_body = "uterus";
  const nlohmann::json report = sim::report_to_json(sim::run_headless(scenario, options));
  ASSERT_TRUE(report["score"].is_null());
  const auto dir = viscera::testing::scratch_dir();
  write_html_report(report, nullptr, dir);
  const std::string html = viscera::testing::file_bytes(dir / "report.html");
  const std::size_t row = html.find("<tr><td>Score</td>");
  ASSERT_NE(row, std::string::npos);
  const std::string score = html.substr(row, html.find("</tr>", row) - row);
  EXPECT_NE(score.find("not assessed: the instrument never moved"), std::string::npos) << score;
  EXPECT_EQ(score.find("/ 100"), std::string::npos) << score;
  EXPECT_TRUE(std::filesystem::exists(dir / "scores.png"));
}

TEST(HtmlReport, a_session_with_distension_fluid_plots_its_deficit_and_tables_the_balance) {
  core::Scenario scenario = viscera::testing::cavity_scenario();
  scenario.fluid.enabled = true;
  const nlohmann::json report = scripted_report(viscera::testing::expert_cavity_script(), scenario);
  ASSERT_FALSE(report["fluid_series"].is_null());
  ASSERT_GT(report["fluid_series"]["time"].size(), 10u);
  const auto dir = viscera::testing::scratch_dir();
  const auto written = write_html_report(report, nullptr, dir);
  EXPECT_EQ(written.back(), dir / "fluid.png");
  const std::string html = viscera::testing::file_bytes(dir / "report.html");
  const auto images = referenced_images(html);
  ASSERT_EQ(images.size(), 5u);
  EXPECT_EQ(images.back(), "fluid.png");
  const auto png = view::decode_png(viscera::testing::file_bytes(dir / "fluid.png"), "fluid.png");
  EXPECT_GT(viscera::testing::frame_statistics(png, 0.0).luminance_stddev, 10.0);
  for (const char* row : {"<h2>Fluid and bleeding</h2>", "<td>Deficit (ml)</td>",
                          "<td>Mean cavity pressure (mmHg)</td>"})
    EXPECT_NE(html.find(row), std::string::npos) << row;
  // The table's deficit is the report's, in ml.
  const std::size_t at = html.find("<td>Deficit (ml)</td><td>");
  ASSERT_NE(at, std::string::npos);
  const double shown = std::stod(html.substr(at + std::string("<td>Deficit (ml)</td><td>").size()));
  EXPECT_NEAR(shown, 1e6 * report["fluid"]["deficit"].get<double>(),
              0.01 * std::abs(1e6 * report["fluid"]["deficit"].get<double>()) + 1e-3);
}

TEST(HtmlReport, a_resection_tables_each_pathology_its_chips_and_the_wall) {
  // The loop scoops the polyp's apex (tests/support/polyp_scoop.h).
  const core::Scenario scenario = viscera::testing::resectoscope_patient();
  const nlohmann::json report = scripted_report(
      viscera::testing::scoop_script(viscera::testing::frame_of(scenario), 2e-3), scenario);
  const nlohmann::json& cutting = report["cutting"];
  ASSERT_TRUE(cutting.is_object());
  const auto dir = viscera::testing::scratch_dir();
  write_html_report(report, nullptr, dir);
  const std::string html = viscera::testing::file_bytes(dir / "report.html");
  EXPECT_NE(html.find("<h2>Resection</h2>"), std::string::npos);
  // The polyp's row: its resected share in %, as the report has it.
  const std::string polyp = "<tr><td>polyp-1</td><td>";
  const std::size_t at = html.find(polyp);
  ASSERT_NE(at, std::string::npos);
  double fraction = -1.0;
  for (const auto& body : cutting["pathologies"])
    if (body["body"] == "polyp-1") fraction = body["resected_fraction"].get<double>();
  ASSERT_GT(fraction, 0.0);
  EXPECT_NEAR(std::stod(html.substr(at + polyp.size())), 100.0 * fraction, 0.01 * 100.0 * fraction);
  // The wall's rows are the report's, in mm and mm³ (the scoop's ends reach the wall beside the
  // polyp), or a dash where it has none.
  const auto shown = [&html](const std::string& label) {
    const std::string cell = "<td>" + label + "</td><td>";
    const std::size_t row = html.find(cell);
    EXPECT_NE(row, std::string::npos) << label;
    return row == std::string::npos ? std::string() : html.substr(row + cell.size(), 16);
  };
  for (const auto& [label, key, scale] :
       {std::tuple{"Deepest cut into the wall (mm)", "deepest_wall_cut", 1e3},
        std::tuple{"Wall thickness there (mm)", "wall_thickness_at_deepest_cut", 1e3},
        std::tuple{"Healthy wall removed (mm³)", "healthy_wall_removed", 1e9}}) {
    const std::string text = shown(label);
    if (cutting[key].is_null()) {
      EXPECT_EQ(text.rfind("&ndash;", 0), 0u) << label;
    } else {
      const double value = scale * cutting[key].get<double>();
      EXPECT_NEAR(std::stod(text), value, 0.01 * std::abs(value) + 1e-12) << label;
    }
  }
  // A session whose instrument cannot cut has no such table.
  const nlohmann::json looking = scripted_report(viscera::testing::expert_cavity_script());
  const auto plain = viscera::testing::scratch_dir();
  write_html_report(looking, nullptr, plain);
  EXPECT_EQ(viscera::testing::file_bytes(plain / "report.html").find("<h2>Resection</h2>"),
            std::string::npos);
}

TEST(HtmlReport, refuses_what_is_not_a_session_report) {
  const auto dir = viscera::testing::scratch_dir();
  EXPECT_THROW(write_html_report(nlohmann::json{{"format", "other"}}, nullptr, dir),
               core::InputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "report.html"));
}

}  // namespace
}  // namespace viscera::report
