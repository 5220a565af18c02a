#include "core/progress.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "core/error.h"

namespace viscera::core {
namespace {

TEST(Progress, reports_stage_fractions_in_order) {
  std::vector<double> fractions;
  Progress progress([&](double f, const std::string& stage) {
    EXPECT_EQ(stage, "meshing");
    fractions.push_back(f);
  });
  progress.begin_stage("meshing", 4);
  for (int i = 0; i < 4; ++i)
    progress.step();
  ASSERT_EQ(fractions.size(), 5u);
  EXPECT_EQ(fractions.front(), 0.0);
  EXPECT_EQ(fractions.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_DOUBLE_EQ(progress.fraction(), 1.0);
}

TEST(Progress, throttles_callbacks_to_one_per_permille) {
  int calls = 0;
  Progress progress([&](double, const std::string&) { ++calls; });
  progress.begin_stage("many", 1000000);
  for (int i = 0; i < 1000000; ++i)
    progress.step();
  EXPECT_LE(calls, 1001 + 1);
}

TEST(Progress, cancel_makes_the_next_step_throw) {
  Progress progress;
  progress.begin_stage("long work", 10);
  progress.step();
  progress.cancel();
  EXPECT_TRUE(progress.cancelled());
  EXPECT_THROW(progress.step(), CancelledError);
  EXPECT_THROW(progress.check_cancelled(), CancelledError);
}

TEST(ExitCodes, follow_the_command_line_contract) {
  EXPECT_EQ(exit_code_for(UsageError("x")), ExitCode::Usage);
  EXPECT_EQ(exit_code_for(InputError("x")), ExitCode::InvalidInput);
  EXPECT_EQ(exit_code_for(UnsupportedVersionError("x")), ExitCode::InvalidInput);
  EXPECT_EQ(exit_code_for(ValidationError("x")), ExitCode::ValidationFailed);
  EXPECT_EQ(exit_code_for(OutputError("x")), ExitCode::InternalError);
  EXPECT_EQ(exit_code_for(std::runtime_error("x")), ExitCode::InternalError);
}

TEST(Error, message_names_file_pointer_and_element_first) {
  const ValidationError e("unknown material id \"myo\"",
                          {"p.vscene/manifest.json", "/scenario/objects/3/material", ""});
  EXPECT_STREQ(e.what(),
               "p.vscene/manifest.json: /scenario/objects/3/material: unknown material id \"myo\"");
  EXPECT_EQ(e.reason(), "unknown material id \"myo\"");
  EXPECT_EQ(e.location().json_pointer, "/scenario/objects/3/material");
}

}  // namespace
}  // namespace viscera::core
