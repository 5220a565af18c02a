#pragma once
/// Runs the project's command-line programs from tests and captures what they print.

#include <filesystem>
#include <string>

namespace viscera::testing {

/// Exit code and output of one command.
struct CommandResult {
  int exit_code = -1;
  std::string out;  ///< standard output
  std::string err;  ///< standard error
};

/// Runs `program` (a file name in the build's bin/ folder) with `arguments` (already quoted
/// for the shell) through /bin/sh, with stdout and stderr captured in files under `work_dir`.
CommandResult run_program(const std::string& program, const std::string& arguments,
                          const std::filesystem::path& work_dir);

/// Single-quotes a path or word for the shell.
std::string shell_quote(const std::string& word);

}  // namespace viscera::testing
