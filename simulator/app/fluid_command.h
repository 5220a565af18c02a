#pragma once
/// `viscera-sim fluid cavity --re R --grid N [--first-order] [--json]`: the flow solver's
/// validation on the lid-driven cavity against Ghia, Ghia & Shin 1982 (simulator/fluid).

#include <CLI/CLI.hpp>

/// Adds the `fluid` command group to `app`; a run sets `exit_code` (0).
void add_fluid_command(CLI::App& app, int& exit_code);
