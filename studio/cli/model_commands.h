#pragma once
/// `viscera model new|points|move-point|branch|layer|material|fix|connect|mesh|package …`: the
/// modelling kernel from the command line (seed 001 §3.3; core/modelling/model_document.h).
/// Edits rewrite the model JSON in place unless -o names another file.

#include <CLI/CLI.hpp>

namespace viscera::cli {

/// Adds the model subcommand and its actions to `app`.
void add_model_commands(CLI::App& app);

}  // namespace viscera::cli
