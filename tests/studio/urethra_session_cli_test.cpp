// The urethra end to end (issue 8 item 2, seed 002): `viscera new --template urethra` and
// `viscera-sim run PKG --headless --script data/scripts/urethra-expert.json --report OUT` run
// the insertion procedure on the lattice's force model to completion below the warning level,
// and `viscera-sim replay` of its trace finds every state hash again.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"

namespace viscera {
namespace {

using testing::run_program;
using testing::shell_quote;

TEST(UrethraSessionCli, expert_script_completes_the_insertion_and_replays) {
  const auto dir = testing::scratch_dir();
  const auto package = dir / "u.vscene";
  ASSERT_EQ(
      run_program("viscera", "new --template urethra -o " + shell_quote(package.string()), dir)
          .exit_code,
      0);
  const auto script = testing::source_dir() / "data" / "scripts" / "urethra-expert.json";
  const auto out = dir / "expert";
  const auto result =
      run_program("viscera-sim",
                  "run " + shell_quote(package.string()) + " --headless --script " +
                      shell_quote(script.string()) + " --report " + shell_quote(out.string()),
                  dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  std::ifstream in(out / "report.json");
  const nlohmann::json report = nlohmann::json::parse(in);
  EXPECT_EQ(report.at("end_reason"), "completed");
  ASSERT_EQ(report.at("tasks").size(), 4u);
  for (const auto& task : report.at("tasks"))
    EXPECT_EQ(task.at("status"), "completed") << task;
  const double max_force = report.at("metrics").at("max_force").get<double>();
  EXPECT_GT(max_force, 0.5);
  EXPECT_LT(max_force, report.at("force_warning").get<double>());
  for (const auto& event : report.at("events")) {
    EXPECT_NE(event.at("kind"), "force-warning") << event;
    EXPECT_NE(event.at("kind"), "excessive-force") << event;
  }
  const auto replay =
      run_program("viscera-sim", "replay " + shell_quote((out / "trace.json").string()), dir);
  EXPECT_EQ(replay.exit_code, 0) << replay.err;
  EXPECT_NE(replay.out.find("replay identical"), std::string::npos) << replay.out;
}

}  // namespace
}  // namespace viscera
