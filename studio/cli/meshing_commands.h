#pragma once
/// Meshing subcommands (issue 3 §3–4, DESIGN.md §9): `viscera mesh surface` (label map →
/// surfaces), `viscera mesh tets` (label map or closed surface → tets with the embedded visual
/// surface and a quality report) and `viscera mesh quality` (a tet mesh's quality report).

#include <CLI/CLI.hpp>

namespace viscera::cli {

/// Adds `surface` to the `mesh` subcommand.
void add_mesh_surface_command(CLI::App& mesh);
/// Adds `tets` and `quality` to the `mesh` subcommand.
void add_mesh_tets_commands(CLI::App& mesh);

}  // namespace viscera::cli
