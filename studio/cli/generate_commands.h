#pragma once
/// `viscera generate`: many validated virtual patients from one template (issue 6 §4).

#include <CLI/CLI.hpp>

namespace viscera::cli {

/// Registers `generate`; the command leaves its exit code in `exit_code`.
void add_generate_commands(CLI::App& app, int& exit_code);

}  // namespace viscera::cli
