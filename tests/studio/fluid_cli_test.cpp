// `viscera-sim fluid cavity` (issue 18 §2): the validation entry prints the two centre lines with
// Ghia et al.'s values beside them and the RMS errors, exits 0 when the cavity reached steady
// state, and refuses a Reynolds number without a reference table with exit 2.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"

using namespace viscera;

TEST(FluidCli, the_cavity_prints_its_centre_lines_against_ghia) {
  const auto dir = viscera::testing::scratch_dir();
  const auto run =
      viscera::testing::run_program("viscera-sim", "fluid cavity --re 100 --grid 32 --json", dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json report = nlohmann::json::parse(run.out);
  EXPECT_EQ(report.at("format"), "viscera-cavity-validation");
  EXPECT_TRUE(report.at("steady").get<bool>());
  ASSERT_EQ(report.at("u_vertical").size(), 17u);
  ASSERT_EQ(report.at("v_horizontal").size(), 17u);
  // The printed RMS is the RMS of the printed points.
  double sum = 0.0;
  for (const auto& point : report.at("u_vertical"))
    sum += std::pow(point.at("u").get<double>() - point.at("ghia").get<double>(), 2);
  EXPECT_NEAR(std::sqrt(sum / 17.0), report.at("u_rms_error").get<double>(), 1e-12);
  EXPECT_LT(report.at("u_rms_error").get<double>(), 0.05);
  EXPECT_LT(report.at("v_rms_error").get<double>(), 0.05);

  const auto refused = viscera::testing::run_program("viscera-sim", "fluid cavity --re 1000", dir);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("--re"), std::string::npos) << refused.err;
}
