#pragma once
/// A project program started as a real child process that a test can kill at a chosen moment.

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace viscera::testing {

/// How a killed run ended.
struct KilledRun {
  bool finished_first = false;  ///< the program had exited before the kill
  int exit_code = -1;           ///< its exit code when it finished first
};

/// Starts `program` (a file name in the build's bin/ folder) with `arguments` in `work_dir`
/// (stdout and stderr to /dev/null), sends it SIGKILL after `delay` unless it has exited by
/// then, and reaps it.
KilledRun run_and_kill(const std::string& program, const std::vector<std::string>& arguments,
                       const std::filesystem::path& work_dir, std::chrono::microseconds delay);

}  // namespace viscera::testing
