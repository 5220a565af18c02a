// The flow solver's validation (issue 18 §2): the lid-driven cavity reaches steady state and its
// centre lines match Ghia, Ghia & Shin 1982 within 5 % RMS of the lid speed.

#include "simulator/fluid/lid_driven_cavity.h"

#include <gtest/gtest.h>

#include "core/error.h"

using namespace viscera;
using namespace viscera::sim::fluid;

TEST(LidDrivenCavity, re_100_on_32_cells_matches_ghia_within_5_percent) {
  CavityRun run;
  run.threads = 1;  // ctest runs suites side by side: no OpenMP workers spinning against them
  run.reynolds = 100.0;
  run.grid = 32;
  const CavityResult result = run_lid_driven_cavity(run);
  EXPECT_TRUE(result.steady) << "rate " << result.final_rate;
  EXPECT_LE(result.max_divergence, run.divergence_tolerance);
  EXPECT_LT(result.u_rms_error, 0.05);
  EXPECT_LT(result.v_rms_error, 0.05);
  // The primary vortex: u reverses below the lid, v is down near the right wall and up near the
  // left one.
  EXPECT_LT(result.u_vertical[8].computed, -0.15);   // y = 0.5
  EXPECT_LT(result.v_horizontal[7].computed, -0.2);  // x = 0.8047
  EXPECT_GT(result.v_horizontal[9].computed, 0.15);  // x = 0.2344
  const nlohmann::json json = to_json(result);
  EXPECT_EQ(json.at("u_vertical").size(), 17u);
  EXPECT_EQ(json.at("format"), "viscera-cavity-validation");
}

TEST(LidDrivenCavity, first_order_advection_is_further_from_the_reference) {
  CavityRun run;
  run.threads = 1;  // ctest runs suites side by side: no OpenMP workers spinning against them
  run.grid = 32;
  const CavityResult second = run_lid_driven_cavity(run);
  run.second_order = false;
  const CavityResult first = run_lid_driven_cavity(run);
  EXPECT_TRUE(first.steady);
  EXPECT_GT(first.u_rms_error + first.v_rms_error, second.u_rms_error + second.v_rms_error);
}

TEST(LidDrivenCavity, a_reynolds_number_without_a_table_is_refused) {
  CavityRun run;
  run.threads = 1;  // ctest runs suites side by side: no OpenMP workers spinning against them
  run.reynolds = 1000.0;
  EXPECT_THROW(run_lid_driven_cavity(run), core::UsageError);
  run.reynolds = 100.0;
  run.grid = 4;
  EXPECT_THROW(run_lid_driven_cavity(run), core::UsageError);
}

TEST(LidDrivenCavity, re_400_on_64_cells_matches_ghia_within_5_percent) {
  CavityRun run;
  run.threads = 1;  // ctest runs suites side by side: no OpenMP workers spinning against them
  run.reynolds = 400.0;
  run.grid = 64;
  const CavityResult result = run_lid_driven_cavity(run);
  EXPECT_TRUE(result.steady) << "rate " << result.final_rate;
  EXPECT_LT(result.u_rms_error, 0.05);
  EXPECT_LT(result.v_rms_error, 0.05);
}
