// `kill -9` at random moments during `viscera pack`, `viscera new` writing a package folder
// (the studio's save writes packages the same way, through core::write_package) and
// `viscera export` leaves the previous output whole under its name and, after the next run,
// no staging behind (issue 21 §4). Real child processes, real SIGKILL.
#include <gtest/gtest.h>

#include <chrono>
#include <random>

#include "core/package/scenario_package.h"
#include "tests/support/child_process.h"
#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"

namespace viscera {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr int kKills = 10;

/// Hidden entries beside `target` that belong to it (staging of a write).
std::vector<std::string> staging_beside(const fs::path& target) {
  std::vector<std::string> found;
  const std::string prefix = "." + target.filename().string();
  for (const auto& entry : fs::directory_iterator(target.parent_path())) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) == 0) found.push_back(name);
  }
  return found;
}

/// Wall time of one complete run, to spread the kills over it.
std::chrono::microseconds time_of(const std::string& program, const std::vector<std::string>& args,
                                  const fs::path& dir) {
  const auto start = Clock::now();
  const auto run = testing::run_and_kill(program, args, dir, std::chrono::minutes(5));
  EXPECT_TRUE(run.finished_first);
  EXPECT_EQ(run.exit_code, 0);
  return std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - start);
}

/// Runs `args` kKills times, each killed at a random moment within 1.2× its duration, and
/// calls `check` after each; then once to completion, after which no staging may remain.
template <typename Check>
void kill_repeatedly(const std::vector<std::string>& args, const fs::path& dir,
                     const fs::path& target, Check check) {
  const auto duration = time_of("viscera", args, dir);
  std::mt19937 random(21);
  std::uniform_int_distribution<long> moment(0, duration.count() * 6 / 5);
  int killed = 0;
  for (int k = 0; k < kKills; ++k) {
    const auto run = testing::run_and_kill("viscera", args, dir,
                                           std::chrono::microseconds(moment(random)));
    if (!run.finished_first) ++killed;
    check(k);
  }
  EXPECT_GT(killed, kKills / 2) << "most runs must be killed before they finish";
  time_of("viscera", args, dir);
  check(kKills);
  EXPECT_TRUE(staging_beside(target).empty()) << staging_beside(target).front();
}

std::uint64_t seed_of(const fs::path& package) { return core::summarize_package(package).seed; }

TEST(KillSafety, pack_killed_at_any_moment_leaves_the_previous_archive_whole) {
  const fs::path dir = testing::scratch_dir();
  for (const char* seed : {"1", "2"}) {
    const auto made = testing::run_program(
        "viscera", std::string("new --template ball --seed ") + seed + " -o p" + seed + ".vscene",
        dir);
    ASSERT_EQ(made.exit_code, 0) << made.err;
  }
  ASSERT_EQ(testing::run_program("viscera", "pack p1.vscene -o out.vscz", dir).exit_code, 0);
  kill_repeatedly({"pack", "p2.vscene", "-o", "out.vscz"}, dir, dir / "out.vscz", [&](int k) {
    ASSERT_TRUE(fs::exists(dir / "out.vscz")) << "after kill " << k;
    EXPECT_TRUE(core::validate_package(dir / "out.vscz").empty()) << "after kill " << k;
  });
  EXPECT_EQ(seed_of(dir / "out.vscz"), seed_of(dir / "p2.vscene"));
}

TEST(KillSafety, a_package_folder_rewritten_and_killed_at_any_moment_stays_whole) {
  const fs::path dir = testing::scratch_dir();
  ASSERT_EQ(
      testing::run_program("viscera", "new --template ball --seed 1 -o out.vscene", dir).exit_code,
      0);
  kill_repeatedly({"new", "--template", "ball", "--seed", "2", "-o", "out.vscene"}, dir,
                  dir / "out.vscene", [&](int k) {
                    ASSERT_TRUE(fs::is_directory(dir / "out.vscene")) << "after kill " << k;
                    EXPECT_TRUE(core::validate_package(dir / "out.vscene").empty())
                        << "after kill " << k;
                  });
}

TEST(KillSafety, export_killed_at_any_moment_leaves_the_previous_file_whole) {
  const fs::path dir = testing::scratch_dir();
  for (const char* seed : {"1", "2"}) {
    ASSERT_EQ(testing::run_program("viscera",
                                   std::string("new --template ball --seed ") + seed + " -o p" +
                                       seed + ".vscene",
                                   dir)
                  .exit_code,
              0);
    ASSERT_EQ(testing::run_program("viscera",
                                   std::string("export p") + seed + ".vscene --format glb -o e" +
                                       seed + ".glb",
                                   dir)
                  .exit_code,
              0);
  }
  const std::string old_bytes = testing::file_bytes(dir / "e1.glb");
  const std::string new_bytes = testing::file_bytes(dir / "e2.glb");
  ASSERT_NE(old_bytes, new_bytes);
  fs::copy_file(dir / "e1.glb", dir / "out.glb");
  kill_repeatedly({"export", "p2.vscene", "--format", "glb", "-o", "out.glb"}, dir,
                  dir / "out.glb", [&](int k) {
                    const std::string bytes = testing::file_bytes(dir / "out.glb");
                    EXPECT_TRUE(bytes == old_bytes || bytes == new_bytes)
                        << "after kill " << k << ": a mixed or partial file";
                  });
  EXPECT_EQ(testing::file_bytes(dir / "out.glb"), new_bytes);
}

}  // namespace
}  // namespace viscera
