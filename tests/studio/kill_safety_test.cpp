// `kill -9` at random moments during `viscera pack`, `viscera new` writing a package folder
// (the studio's save writes packages the same way, through core::write_package) and
// `viscera export` leaves the previous output whole under its name and, after the next run,
// no staging behind (issue 21 §4). Real child processes, real SIGKILL.
#include <gtest/gtest.h>

#include <algorithm>
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

constexpr int kKills = 16;

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

/// Wall time of a complete run, the shortest of three (the first run of a program pays for a
/// cold file cache), to spread the kills over it.
std::chrono::microseconds time_of(const std::string& program, const std::vector<std::string>& args,
                                  const fs::path& dir) {
  auto shortest = std::chrono::microseconds::max();
  for (int run_index = 0; run_index < 3; ++run_index) {
    const auto start = Clock::now();
    const auto run = testing::run_and_kill(program, args, dir, std::chrono::minutes(5));
    EXPECT_TRUE(run.finished_first);
    EXPECT_EQ(run.exit_code, 0);
    shortest = std::min(
        shortest, std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - start));
  }
  return shortest;
}

/// Runs `args` kKills times, each killed at a random moment between the end of the program's
/// start-up (loading its libraries takes most of a short run) and its whole duration, and
/// calls `check` after each; then once to completion, after which no staging may remain.
template <typename Check>
void kill_repeatedly(const std::vector<std::string>& args, const fs::path& dir,
                     const fs::path& target, Check check) {
  const auto start_up = time_of("viscera", {"--version"}, dir);
  const auto duration = time_of("viscera", args, dir);
  std::mt19937 random(21);
  long low = start_up.count() * 9 / 10;
  long high = std::max(start_up.count(), duration.count());
  int killed = 0;
  // kKills runs; while none has been killed yet (a loaded machine makes the timed runs slower
  // than the later ones), each run that finished first halves the window towards its start, and
  // the start itself once the window is under a millisecond, for up to 4·kKills runs.
  for (int k = 0; k < kKills || (killed == 0 && k < 4 * kKills); ++k) {
    const long at = std::uniform_int_distribution<long>(low, std::max(low, high))(random);
    const auto run = testing::run_and_kill("viscera", args, dir, std::chrono::microseconds(at));
    if (!run.finished_first) ++killed;
    if (run.finished_first && killed == 0) {
      high = low + (high - low) / 2;
      if (high - low < 1000) low /= 2;
    }
    check(k);
  }
  EXPECT_GT(killed, 0) << "no run was killed before it finished";
  time_of("viscera", args, dir);
  check(kKills);
  EXPECT_TRUE(staging_beside(target).empty()) << staging_beside(target).front();
}

std::string quoted(const fs::path& path) {
  return testing::shell_quote(path.string());
}

/// Runs `viscera ARGUMENTS` to completion; returns its exit code.
int viscera(const std::string& arguments, const fs::path& dir) {
  const auto result = testing::run_program("viscera", arguments, dir);
  EXPECT_EQ(result.exit_code, 0) << arguments << ": " << result.err;
  return result.exit_code;
}

/// A ball patient; seed 2 is also smaller, so its files differ from seed 1's.
void make_ball(const std::string& seed, const fs::path& package) {
  const std::string size = seed == "2" ? " --set radius=0.03" : "";
  ASSERT_EQ(viscera("new --template ball --seed " + seed + size + " -o " + quoted(package),
                    package.parent_path()),
            0);
}

std::uint64_t seed_of(const fs::path& package) {
  return core::summarize_package(package).seed;
}

TEST(KillSafety, pack_killed_at_any_moment_leaves_the_previous_archive_whole) {
  const fs::path dir = testing::scratch_dir();
  for (const char* seed : {"1", "2"})
    make_ball(seed, dir / (std::string("p") + seed + ".vscene"));
  ASSERT_EQ(viscera("pack " + quoted(dir / "p1.vscene") + " -o " + quoted(dir / "out.vscz"), dir),
            0);
  kill_repeatedly({"pack", (dir / "p2.vscene").string(), "-o", (dir / "out.vscz").string()}, dir,
                  dir / "out.vscz", [&](int k) {
                    ASSERT_TRUE(fs::exists(dir / "out.vscz")) << "after kill " << k;
                    EXPECT_TRUE(core::validate_package(dir / "out.vscz").empty())
                        << "after kill " << k;
                  });
  EXPECT_EQ(seed_of(dir / "out.vscz"), seed_of(dir / "p2.vscene"));
}

TEST(KillSafety, a_package_folder_replaced_and_killed_at_any_moment_stays_whole) {
  // `viscera unpack` spends its time writing a package folder, which it then swaps in the way
  // every package write does (core::write_package: `viscera new`, the studio's save).
  const fs::path dir = testing::scratch_dir();
  make_ball("1", dir / "out.vscene");
  make_ball("2", dir / "p2.vscene");
  ASSERT_EQ(viscera("pack " + quoted(dir / "p2.vscene") + " -o " + quoted(dir / "p2.vscz"), dir),
            0);
  kill_repeatedly({"unpack", (dir / "p2.vscz").string(), "-o", (dir / "out.vscene").string()}, dir,
                  dir / "out.vscene", [&](int k) {
                    ASSERT_TRUE(fs::is_directory(dir / "out.vscene")) << "after kill " << k;
                    EXPECT_TRUE(core::validate_package(dir / "out.vscene").empty())
                        << "after kill " << k;
                  });
  EXPECT_EQ(seed_of(dir / "out.vscene"), 2u);
}

TEST(KillSafety, export_killed_at_any_moment_leaves_the_previous_file_whole) {
  const fs::path dir = testing::scratch_dir();
  for (const char* seed : {"1", "2"}) {
    const fs::path package = dir / (std::string("p") + seed + ".vscene");
    make_ball(seed, package);
    ASSERT_EQ(viscera("export " + quoted(package) + " --format glb -o " +
                          quoted(dir / (std::string("e") + seed + ".glb")),
                      dir),
              0);
  }
  const std::string old_bytes = testing::file_bytes(dir / "e1.glb");
  const std::string new_bytes = testing::file_bytes(dir / "e2.glb");
  ASSERT_FALSE(old_bytes.empty());
  ASSERT_TRUE(old_bytes != new_bytes) << "the two exports must differ for the test to see a mix";
  fs::copy_file(dir / "e1.glb", dir / "out.glb");
  kill_repeatedly(
      {"export", (dir / "p2.vscene").string(), "--format", "glb", "-o", (dir / "out.glb").string()},
      dir, dir / "out.glb", [&](int k) {
        const std::string bytes = testing::file_bytes(dir / "out.glb");
        EXPECT_TRUE(bytes == old_bytes || bytes == new_bytes)
            << "after kill " << k << ": a mixed or partial file";
      });
  EXPECT_EQ(testing::file_bytes(dir / "out.glb"), new_bytes);
}

}  // namespace
}  // namespace viscera
