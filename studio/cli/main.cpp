/// `viscera`: the command-line twin of every studio action (DESIGN.md §9).
/// Exit codes: 0 success, 1 internal error, 2 usage, 3 unreadable or invalid input,
/// 4 validation failed.

#include <CLI/CLI.hpp>
#include <iostream>

#include "core/cli/command_line.h"
#include "studio/cli/export_commands.h"
#include "studio/cli/generate_commands.h"
#include "studio/cli/library_commands.h"
#include "studio/cli/material_commands.h"
#include "studio/cli/mesh_commands.h"
#include "studio/cli/model_commands.h"
#include "studio/cli/package_commands.h"
#include "studio/cli/segment_commands.h"
#include "studio/cli/template_commands.h"
#include "studio/cli/texture_commands.h"
#include "studio/cli/vessel_commands.h"
#include "studio/cli/volume_commands.h"

int main(int argc, char** argv) {
  CLI::App app{"Viscera: virtual patients for surgical simulators", "viscera"};
  app.require_subcommand(1);
  viscera::cli::add_common_options(app);

  int exit_code = 0;
  viscera::cli::add_template_commands(app);
  viscera::cli::add_package_commands(app, exit_code);
  viscera::cli::add_texture_commands(app);
  viscera::cli::add_vessel_commands(app);
  viscera::cli::add_mesh_commands(app);
  viscera::cli::add_export_commands(app);
  viscera::cli::add_generate_commands(app, exit_code);
  viscera::cli::add_volume_commands(app);
  viscera::cli::add_segment_commands(app);
  viscera::cli::add_library_commands(app);
  viscera::cli::add_material_commands(app);
  viscera::cli::add_model_commands(app);

  return viscera::cli::run_command_line(app, argc, argv, exit_code);
}
