#pragma once
/// Texture subcommands: `viscera noise X Y Z` and `viscera texture --preset P …` (DESIGN.md §9).

#include <CLI/CLI.hpp>

namespace viscera::cli {

/// Adds the texture subcommands to `app`.
void add_texture_commands(CLI::App& app);

}  // namespace viscera::cli
