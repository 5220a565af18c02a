#pragma once
/// `viscera templates` and `viscera new` (DESIGN.md §9).

#include <CLI/CLI.hpp>

namespace viscera::cli {

/// Adds the `templates` and `new` subcommands to `app`.
void add_template_commands(CLI::App& app);

}  // namespace viscera::cli
