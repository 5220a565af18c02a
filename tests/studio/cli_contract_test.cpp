// The command-line contract of DESIGN.md §9, checked by running the real `viscera` program:
// exit codes 0 success, 2 usage, 3 unreadable or invalid input, 4 validation failed.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"

namespace viscera {
namespace {

using testing::run_program;
using testing::shell_quote;

/// A small ball so each test builds its patient in well under a second.
const char* kSmallBall = "new --template ball --seed 3 --set radius=0.02 --set cell_size=0.008";

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(CliContract, no_command_is_a_usage_error) {
  const auto dir = testing::scratch_dir();
  EXPECT_EQ(run_program("viscera", "", dir).exit_code, 2);
  EXPECT_EQ(run_program("viscera", "frobnicate", dir).exit_code, 2);
}

TEST(CliContract, every_command_has_help) {
  const auto dir = testing::scratch_dir();
  for (const char* command :
       {"templates", "new", "info", "validate", "pack", "unpack", "noise", "mesh convert"}) {
    const auto result = run_program("viscera", std::string(command) + " --help", dir);
    EXPECT_EQ(result.exit_code, 0) << command;
    EXPECT_NE(result.out.find("Usage"), std::string::npos) << command;
  }
}

TEST(CliContract, templates_json_lists_ball_with_units_ranges_and_defaults) {
  const auto dir = testing::scratch_dir();
  const auto result = run_program("viscera", "templates --json", dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto catalog = nlohmann::json::parse(result.out);
  ASSERT_FALSE(catalog.empty());
  EXPECT_EQ(catalog[0]["name"], "ball");
  for (const auto& p : catalog[0]["parameters"]) {
    EXPECT_TRUE(p.contains("unit"));
    EXPECT_LE(p["minimum"].get<double>(), p["default"].get<double>());
    EXPECT_GE(p["maximum"].get<double>(), p["default"].get<double>());
  }
}

TEST(CliContract, bad_template_arguments_are_usage_errors_with_one_line) {
  const auto dir = testing::scratch_dir();
  const auto out = shell_quote((dir / "x.vscene").string());
  auto result = run_program("viscera", "new --template nope -o " + out, dir);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("unknown template \"nope\""), std::string::npos) << result.err;
  result = run_program("viscera", "new --template ball --set radius=abc -o " + out, dir);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("radius"), std::string::npos) << result.err;
  result = run_program("viscera", "new --template ball --set radius=9 -o " + out, dir);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_FALSE(std::filesystem::exists(dir / "x.vscene"));
}

TEST(CliContract, new_writes_a_package_that_validates_and_describes_itself) {
  const auto dir = testing::scratch_dir();
  const auto package = (dir / "ball.vscene").string();
  auto result =
      run_program("viscera", std::string(kSmallBall) + " -o " + shell_quote(package), dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  result = run_program("viscera", "validate " + shell_quote(package), dir);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  result = run_program("viscera", "info --json " + shell_quote(package), dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto info = nlohmann::json::parse(result.out);
  EXPECT_EQ(info["template"], "ball");
  EXPECT_EQ(info["seed"], 3);
  EXPECT_EQ(info["objects"], 1);
  EXPECT_GT(info["body_tets"].get<int>(), 100);
}

TEST(CliContract, same_seed_gives_identical_package_bytes) {
  const auto dir = testing::scratch_dir();
  for (const char* name : {"a.vscz", "b.vscz"}) {
    ASSERT_EQ(
        run_program("viscera",
                    std::string(kSmallBall) + " -o " + shell_quote((dir / name).string()), dir)
            .exit_code,
        0);
  }
  EXPECT_EQ(read_text(dir / "a.vscz"), read_text(dir / "b.vscz"));
}

TEST(CliContract, hand_edited_manifest_fails_validation_naming_file_and_pointer) {
  const auto dir = testing::scratch_dir();
  const auto package = dir / "ball.vscene";
  ASSERT_EQ(
      run_program("viscera", std::string(kSmallBall) + " -o " + shell_quote(package.string()), dir)
          .exit_code,
      0);
  auto manifest = nlohmann::json::parse(read_text(package / "manifest.json"));
  manifest["scenario"]["objects"][0]["material"] = "myo";
  std::ofstream(package / "manifest.json") << manifest.dump(2);
  const auto result = run_program("viscera", "validate " + shell_quote(package.string()), dir);
  EXPECT_EQ(result.exit_code, 4) << result.out << result.err;
  EXPECT_NE(result.err.find("manifest.json"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("/scenario/objects/0/material"), std::string::npos) << result.err;
}

TEST(CliContract, unreadable_input_exits_3) {
  const auto dir = testing::scratch_dir();
  auto result =
      run_program("viscera", "validate " + shell_quote((dir / "missing.vscene").string()), dir);
  EXPECT_EQ(result.exit_code, 3) << result.err;
  std::filesystem::create_directories(dir / "broken.vscene");
  std::ofstream(dir / "broken.vscene" / "manifest.json") << "{ not json";
  result = run_program("viscera", "info " + shell_quote((dir / "broken.vscene").string()), dir);
  EXPECT_EQ(result.exit_code, 3) << result.err;
  EXPECT_NE(result.err.find("manifest.json"), std::string::npos) << result.err;
}

TEST(CliContract, pack_and_unpack_round_trip) {
  const auto dir = testing::scratch_dir();
  const auto folder = dir / "ball.vscene";
  ASSERT_EQ(
      run_program("viscera", std::string(kSmallBall) + " -o " + shell_quote(folder.string()), dir)
          .exit_code,
      0);
  const auto zipped = dir / "ball.vscz";
  ASSERT_EQ(run_program(
                "viscera",
                "pack " + shell_quote(folder.string()) + " -o " + shell_quote(zipped.string()), dir)
                .exit_code,
            0);
  const auto unpacked = dir / "again.vscene";
  ASSERT_EQ(
      run_program(
          "viscera",
          "unpack " + shell_quote(zipped.string()) + " -o " + shell_quote(unpacked.string()), dir)
          .exit_code,
      0);
  EXPECT_EQ(read_text(folder / "manifest.json"), read_text(unpacked / "manifest.json"));
  EXPECT_EQ(run_program("viscera", "validate " + shell_quote(unpacked.string()), dir).exit_code, 0);
}

TEST(CliContract, noise_prints_the_reference_value_with_17_digits) {
  const auto dir = testing::scratch_dir();
  const auto result = run_program("viscera", "noise 3.14 42 7", dir);
  ASSERT_EQ(result.exit_code, 0);
  EXPECT_EQ(result.out, "0.13691995878400012\n");
}

TEST(CliContract, headless_session_report_hash_repeats_across_runs) {
  const auto dir = testing::scratch_dir();
  const auto package = dir / "ball.vscz";
  ASSERT_EQ(
      run_program("viscera", std::string(kSmallBall) + " -o " + shell_quote(package.string()), dir)
          .exit_code,
      0);
  std::string hashes[2];
  for (int run = 0; run < 2; ++run) {
    const auto report_dir = dir / ("report" + std::to_string(run));
    const auto result =
        run_program("viscera-sim",
                    "run " + shell_quote(package.string()) +
                        " --headless --duration 0.5 --report " + shell_quote(report_dir.string()),
                    dir);
    ASSERT_EQ(result.exit_code, 0) << result.err;
    const auto report = nlohmann::json::parse(read_text(report_dir / "report.json"));
    hashes[run] = report["final_state_hash"].get<std::string>();
    EXPECT_EQ(hashes[run].size(), 64u);
  }
  EXPECT_EQ(hashes[0], hashes[1]);
}

TEST(CliContract, simulator_refuses_a_missing_package_with_exit_3) {
  const auto dir = testing::scratch_dir();
  const auto result = run_program(
      "viscera-sim", "run " + shell_quote((dir / "none.vscene").string()) + " --headless", dir);
  EXPECT_EQ(result.exit_code, 3) << result.err;
  EXPECT_NE(result.err.find("none.vscene"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace viscera

namespace viscera {
namespace {

TEST(CliContract, recorded_session_replays_identically_and_a_tampered_trace_fails_with_4) {
  const auto dir = testing::scratch_dir();
  const auto package = dir / "ball.vscene";
  ASSERT_EQ(
      run_program("viscera", std::string(kSmallBall) + " -o " + shell_quote(package.string()), dir)
          .exit_code,
      0);
  // The small ball (radius 2 cm) is pressed from above, 6 mm deep, and released.
  std::ofstream(dir / "script.json")
      << R"({"format": "viscera-script", "version": 1, "body": "ball", "stiffness": 200,
    "waypoints": [{"t": 0, "tip": [0, 0, 0.03]}, {"t": 0.3, "tip": [0, 0, 0.012]}, {"t": 0.5, "tip": [0, 0, 0.03]}]})";
  const auto trace = dir / "trace.json";
  auto result = run_program("viscera-sim",
                            "run " + shell_quote(package.string()) + " --headless --script " +
                                shell_quote((dir / "script.json").string()) + " --record " +
                                shell_quote(trace.string()) + " --json",
                            dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto report = nlohmann::json::parse(result.out);
  EXPECT_GE(report["instrument"]["contacts"].get<int>(), 1);
  EXPECT_GT(report["instrument"]["max_force"].get<double>(), 0.0);

  result = run_program("viscera-sim", "replay " + shell_quote(trace.string()) + " --headless", dir);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("replay identical"), std::string::npos) << result.out;

  auto tampered = nlohmann::json::parse(read_text(trace));
  // A scripted session's trace keeps its script: a nanometre on the pressing waypoint departs.
  tampered["script"]["waypoints"][1]["tip"][2] =
      tampered["script"]["waypoints"][1]["tip"][2].get<double>() + 1e-9;
  std::ofstream(dir / "tampered.json") << tampered.dump();
  result =
      run_program("viscera-sim", "replay " + shell_quote((dir / "tampered.json").string()), dir);
  EXPECT_EQ(result.exit_code, 4) << result.out << result.err;
  EXPECT_NE(result.err.find("replay departs from the recording at step"), std::string::npos)
      << result.err;

  std::ofstream(dir / "bad.json")
      << R"({"format": "viscera-script", "version": 1, "body": "ball", "waypoints": []})";
  result = run_program("viscera-sim",
                       "run " + shell_quote(package.string()) + " --headless --script " +
                           shell_quote((dir / "bad.json").string()),
                       dir);
  EXPECT_EQ(result.exit_code, 3) << result.err;  // an invalid script is invalid input
  EXPECT_NE(result.err.find("/waypoints"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace viscera
