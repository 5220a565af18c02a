#include "tests/support/command_runner.h"

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace viscera::testing {
namespace {

std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::string shell_quote(const std::string& word) {
  std::string quoted = "'";
  for (const char c : word) {
    if (c == '\'') {
      quoted += "'\\''";
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

CommandResult run_program(const std::string& program, const std::string& arguments,
                          const std::filesystem::path& work_dir) {
  const auto out_path = work_dir / "command.stdout";
  const auto err_path = work_dir / "command.stderr";
  const std::filesystem::path binary = std::filesystem::path(VISCERA_BINARY_DIR) / "bin" / program;
  const std::string command = shell_quote(binary.string()) + " " + arguments + " >" +
                              shell_quote(out_path.string()) + " 2>" +
                              shell_quote(err_path.string()) + " </dev/null";
  const int status = std::system(command.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_all(out_path);
  result.err = read_all(err_path);
  return result;
}

}  // namespace viscera::testing
