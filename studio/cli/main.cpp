/// `viscera`: the command-line twin of every studio action (DESIGN.md §9).
/// Exit codes: 0 success, 1 internal error, 2 usage, 3 unreadable or invalid input,
/// 4 validation failed.

#include <CLI/CLI.hpp>
#include <iostream>

#include "core/error.h"
#include "core/log.h"
#include "core/version.h"
#include "studio/cli/mesh_commands.h"
#include "studio/cli/package_commands.h"
#include "studio/cli/template_commands.h"
#include "studio/cli/texture_commands.h"

int main(int argc, char** argv) {
  using viscera::core::ExitCode;
  CLI::App app{"Viscera: virtual patients for surgical simulators", "viscera"};
  app.require_subcommand(1);
  app.set_version_flag("--version", viscera::core::viscera_version());
  std::string log_level = "warn";
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error or off")
      ->capture_default_str();
  app.parse_complete_callback([&log_level] { viscera::core::set_log_level(log_level); });

  int exit_code = 0;
  viscera::cli::add_template_commands(app);
  viscera::cli::add_package_commands(app, exit_code);
  viscera::cli::add_texture_commands(app);
  viscera::cli::add_mesh_commands(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return static_cast<int>(ExitCode::Usage);
  } catch (const std::exception& e) {
    std::cerr << "viscera: " << e.what() << "\n";
    return static_cast<int>(viscera::core::exit_code_for(e));
  }
  return exit_code;
}
