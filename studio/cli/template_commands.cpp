#include "studio/cli/template_commands.h"

#include <filesystem>
#include <map>
#include <sstream>

#include "core/error.h"
#include "core/package/scenario_package.h"
#include "simulator/dynamics/hydrometra_sweep.h"
#include "studio/cli/command_output.h"
#include "studio/cli/terminal_progress.h"
#include "templates/template_catalog.h"

namespace viscera::cli {
namespace {

struct NewOptions {
  std::string template_name = "ball";
  std::uint64_t seed = 1;
  std::vector<std::string> settings;
  std::string output;
  bool json = false;
};

std::map<std::string, std::string> parse_settings(const std::vector<std::string>& settings) {
  std::map<std::string, std::string> overrides;
  for (const auto& setting : settings) {
    const auto equals = setting.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw core::UsageError("--set expects name=value, got \"" + setting + "\"");
    }
    overrides[setting.substr(0, equals)] = setting.substr(equals + 1);
  }
  return overrides;
}

void list_templates(bool json) {
  const nlohmann::json catalog = templates::catalog_to_json();
  if (json) {
    print_json(catalog);
    return;
  }
  std::ostringstream out;
  for (const auto& t : catalog) {
    out << t["name"].get<std::string>() << "  (procedure " << t["procedure"].get<std::string>()
        << ", version " << t["version"].get<std::string>() << ")\n  "
        << t["description"].get<std::string>() << "\n";
    for (const auto& p : t["parameters"]) {
      out << "    " << p["name"].get<std::string>() << " = " << p["default"].get<double>() << " "
          << p["unit"].get<std::string>() << "  [" << p["minimum"].get<double>() << ", "
          << p["maximum"].get<double>() << "]  " << p["description"].get<std::string>() << "\n";
    }
  }
  print_text(out.str());
}

void create_patient(const NewOptions& options) {
  TerminalProgress bar;
  core::Scenario scenario = templates::build_from_template(
      options.template_name, parse_settings(options.settings), options.seed, bar.progress());
  // Pipeline step: the cavity's pressure states (seed 000 §2.1) for a scenario with a hydrometra.
  sim::add_hydrometra_states(scenario, bar.progress());
  core::write_package(scenario, options.output, bar.progress());
  if (options.json) {
    print_json({{"package", std::filesystem::absolute(options.output).string()},
                {"template", options.template_name},
                {"seed", options.seed},
                {"parameters", scenario.provenance.parameters}});
  } else {
    print_text("wrote " + std::filesystem::absolute(options.output).string() + "\n");
  }
}

}  // namespace

void add_template_commands(CLI::App& app) {
  auto* list = app.add_subcommand("templates", "List templates and their parameters");
  auto list_json = std::make_shared<bool>(false);
  list->add_flag("--json", *list_json, "Print JSON");
  list->callback([list_json] { list_templates(*list_json); });

  auto* create = app.add_subcommand("new", "Create a virtual patient package from a template");
  auto options = std::make_shared<NewOptions>();
  create->add_option("--template,-t", options->template_name, "Template name")->required();
  create->add_option("--seed", options->seed, "Random seed")->capture_default_str();
  create->add_option("--set", options->settings, "Override a parameter: name=value (repeatable)");
  create->add_option("-o,--output", options->output, "Output package (.vscene folder or .vscz)")
      ->required();
  create->add_flag("--json", options->json, "Print JSON");
  create->callback([options] { create_patient(*options); });
}

}  // namespace viscera::cli
