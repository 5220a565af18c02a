#pragma once
/// `viscera library [--library PATH] list|add|get|rm|export|import …` (DESIGN.md §9): the asset
/// library of models, materials, textures and templates (core/library/asset_library.h).

#include <CLI/CLI.hpp>

namespace viscera::cli {

/// Adds the library subcommand and its actions to `app`.
void add_library_commands(CLI::App& app);

}  // namespace viscera::cli
