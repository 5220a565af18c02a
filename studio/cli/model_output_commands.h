#pragma once
/// `viscera model mesh MODEL -o OUT.vtp [--body OUT.vtu]` and `viscera model package MODEL… -o
/// PKG.vscene`: a model's tessellation and body as VTK files, and models built into a
/// scenario package the simulator loads (core/modelling/model_scene.h).

#include <CLI/CLI.hpp>

namespace viscera::cli {

/// Adds mesh and package under the `model` subcommand.
void add_model_output_commands(CLI::App& model);

}  // namespace viscera::cli
