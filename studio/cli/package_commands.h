#pragma once
/// `viscera info`, `validate`, `pack` and `unpack` on scenario packages (DESIGN.md §4, §9).

#include <CLI/CLI.hpp>

namespace viscera::cli {

/// Adds the package subcommands to `app`. `validate` sets `exit_code` to 4 when the package
/// was read but fails its checks.
void add_package_commands(CLI::App& app, int& exit_code);

}  // namespace viscera::cli
