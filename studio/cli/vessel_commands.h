#pragma once
/// `viscera vessels --domain IN [--terminals N] [--seed N] -o OUT.json [--mesh OUT.vtp]`
/// (DESIGN.md §9): vessel trees grown inside an organ, from an L-system, or from spline pipes.

#include <CLI/CLI.hpp>

namespace viscera::cli {

/// Adds the vessels subcommand to `app`.
void add_vessel_commands(CLI::App& app);

}  // namespace viscera::cli
