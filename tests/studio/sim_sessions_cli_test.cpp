// The end-to-end check on a real template: `viscera-sim run PKG --headless --script
// expert.json --report OUT` and the same with novice.json (data/scripts/) give reports whose
// metrics separate in the expected direction, and the expert's session replays hash for hash.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"

namespace viscera {
namespace {

using testing::run_program;
using testing::shell_quote;

nlohmann::json run_script(const std::filesystem::path& package, const std::string& who,
                          const std::filesystem::path& dir) {
  const auto script =
      testing::source_dir() / "data" / "scripts" / ("hysteroscopy-" + who + ".json");
  const auto out = dir / who;
  const auto result =
      run_program("viscera-sim",
                  "run " + shell_quote(package.string()) + " --headless --script " +
                      shell_quote(script.string()) + " --report " + shell_quote(out.string()),
                  dir);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  std::ifstream in(out / "report.json");
  return nlohmann::json::parse(in);
}

TEST(SimSessionsCli, expert_and_novice_scripts_separate_on_the_hysteroscopy_template) {
  const auto dir = testing::scratch_dir();
  const auto package = dir / "patient.vscene";
  ASSERT_EQ(
      run_program("viscera", "new --template hysteroscopy -o " + shell_quote(package.string()), dir)
          .exit_code,
      0);
  const nlohmann::json expert = run_script(package, "expert", dir);
  const nlohmann::json novice = run_script(package, "novice", dir);
  const auto& e = expert["metrics"];
  const auto& n = novice["metrics"];
  EXPECT_LT(e["path_length"].get<double>(), n["path_length"].get<double>());
  EXPECT_GT(e["economy_of_movement"].get<double>(), n["economy_of_movement"].get<double>());
  EXPECT_LT(e["contacts"].get<int>(), n["contacts"].get<int>());
  EXPECT_LT(e["contact_time"].get<double>(), n["contact_time"].get<double>());
  EXPECT_LT(e["max_force"].get<double>(), n["max_force"].get<double>());
  EXPECT_LT(e["mean_contact_force"].get<double>(), n["mean_contact_force"].get<double>());
  EXPECT_GT(e["view_quality"].get<double>(), n["view_quality"].get<double>());
  EXPECT_GT(expert["score"].get<double>(), novice["score"].get<double>());
  EXPECT_GT(novice["force_warning"].get<double>(), 0.0);
  bool warned = false;
  for (const auto& event : novice["events"])
    warned = warned || event["kind"] == "excessive-force";
  EXPECT_TRUE(warned) << "the novice pushed past the script's 0.3 N warning level";

  const auto replay = run_program(
      "viscera-sim", "replay " + shell_quote((dir / "expert" / "trace.json").string()), dir);
  EXPECT_EQ(replay.exit_code, 0) << replay.err;
  EXPECT_NE(replay.out.find("replay identical"), std::string::npos) << replay.out;
}

}  // namespace
}  // namespace viscera
