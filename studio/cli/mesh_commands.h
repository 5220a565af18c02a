#pragma once
/// Mesh subcommands: `viscera mesh convert` (DESIGN.md §9).

#include <CLI/CLI.hpp>

namespace viscera::cli {

/// Adds `mesh convert` to `app`.
void add_mesh_commands(CLI::App& app);

}  // namespace viscera::cli
