#pragma once
/// Mesh subcommands: `viscera mesh convert|surface|tets|quality` (DESIGN.md §9).

#include <CLI/CLI.hpp>

namespace viscera::cli {

/// Adds `mesh` with convert, surface, tets and quality to `app`.
void add_mesh_commands(CLI::App& app);

}  // namespace viscera::cli
