#pragma once
/// `viscera material fit CSV -o MAT.json …`, `viscera material list`, `viscera material get ID
/// -o MAT.json`: measured tissue materials (seed 001 §3.2; core/materials/).

#include <CLI/CLI.hpp>

namespace viscera::cli {

/// Adds the material subcommand and its actions to `app`.
void add_material_commands(CLI::App& app);

}  // namespace viscera::cli
