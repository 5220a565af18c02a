#pragma once
/// main() plumbing shared by the Viscera programs (`viscera`, `viscera-sim`): CLI11 parsing
/// with the exit codes of DESIGN.md §9 — 0 success (and --help, --version), 1 internal error,
/// 2 usage, 3 unreadable or invalid input, 4 validation failed — and one line on error.
/// Header-only, used by both programs' main(); libraries never include it. It lives in core so
/// that neither program reaches into the other's module (docs/architecture.md, module graph).

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <string>

#include "core/error.h"
#include "core/log.h"
#include "core/version.h"

namespace viscera::cli {

/// Adds --version and --log-level to `app`; the level takes effect once parsing is complete.
inline void add_common_options(CLI::App& app) {
  app.set_version_flag("--version", core::viscera_version());
  auto level = std::make_shared<std::string>("warn");
  app.add_option("--log-level", *level, "trace, debug, info, warn, error or off")
      ->capture_default_str();
  app.parse_complete_callback([level] { core::set_log_level(*level); });
}

/// Parses `argv` and runs the chosen command's callback. Returns `exit_code` as the command
/// left it, 0 for --help and --version, 2 for usage errors, and exit_code_for() of any other
/// exception after printing "<program>: <message>" on standard error.
inline int run_command_line(CLI::App& app, int argc, char** argv, const int& exit_code) {
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
    return static_cast<int>(core::ExitCode::Usage);
  } catch (const std::exception& e) {
    std::cerr << app.get_name() << ": " << e.what() << "\n";
    return static_cast<int>(core::exit_code_for(e));
  }
  return exit_code;
}

}  // namespace viscera::cli
