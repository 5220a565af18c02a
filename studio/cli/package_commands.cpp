#include "studio/cli/package_commands.h"

#include <filesystem>
#include <sstream>

#include "core/error.h"
#include "core/package/scenario_package.h"
#include "studio/cli/command_output.h"

namespace viscera::cli {
namespace {

nlohmann::json summary_to_json(const core::PackageSummary& s) {
  return {{"format", s.format},
          {"version", s.version},
          {"name", s.name},
          {"procedure", s.procedure},
          {"template", s.template_name},
          {"seed", s.seed},
          {"objects", s.object_count},
          {"surface_triangles", s.surface_triangles},
          {"body_nodes", s.body_nodes},
          {"body_tets", s.body_tets},
          {"files", s.file_count},
          {"bytes", s.total_bytes}};
}

void show_info(const std::string& path, bool json) {
  const core::PackageSummary s = core::summarize_package(path);
  if (json) {
    print_json(summary_to_json(s));
    return;
  }
  std::ostringstream out;
  out << path << "\n"
      << "  format      " << s.format << " v" << s.version << "\n"
      << "  name        " << s.name << "\n"
      << "  procedure   " << s.procedure << "\n"
      << "  template    " << s.template_name << " (seed " << s.seed << ")\n"
      << "  objects     " << s.object_count << "\n"
      << "  surfaces    " << s.surface_triangles << " triangles\n"
      << "  bodies      " << s.body_nodes << " nodes, " << s.body_tets << " tets\n"
      << "  files       " << s.file_count << ", " << human_bytes(s.total_bytes) << "\n";
  print_text(out.str());
}

int validate(const std::string& path, bool json) {
  const auto issues = core::validate_package(path);
  if (json) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& issue : issues) {
      list.push_back(
          {{"file", issue.file}, {"pointer", issue.json_pointer}, {"message", issue.message}});
    }
    print_json({{"package", path}, {"valid", issues.empty()}, {"issues", list}});
  } else if (issues.empty()) {
    print_text(path + ": valid\n");
  } else {
    for (const auto& issue : issues) {
      std::cerr << path << "/" << issue.file << ": "
                << (issue.json_pointer.empty() ? "" : issue.json_pointer + ": ") << issue.message
                << "\n";
    }
  }
  return issues.empty() ? 0 : static_cast<int>(core::ExitCode::ValidationFailed);
}

}  // namespace

void add_package_commands(CLI::App& app, int& exit_code) {
  struct Options {
    std::string input, output;
    bool json = false;
  };

  auto* info = app.add_subcommand("info", "Summarise a scenario package");
  auto info_options = std::make_shared<Options>();
  info->add_option("package", info_options->input, "Package (.vscene folder or .vscz)")->required();
  info->add_flag("--json", info_options->json, "Print JSON");
  info->callback([info_options] { show_info(info_options->input, info_options->json); });

  auto* check = app.add_subcommand("validate", "Check a package: schema, references, checksums");
  auto check_options = std::make_shared<Options>();
  check->add_option("package", check_options->input, "Package (.vscene folder or .vscz)")
      ->required();
  check->add_flag("--json", check_options->json, "Print JSON");
  check->callback([check_options, &exit_code] {
    exit_code = validate(check_options->input, check_options->json);
  });

  auto* pack = app.add_subcommand("pack", "Zip a package folder into a .vscz");
  auto pack_options = std::make_shared<Options>();
  pack->add_option("package", pack_options->input, "Package folder")->required();
  pack->add_option("-o,--output", pack_options->output, "Output .vscz")->required();
  pack->callback([pack_options] {
    core::pack_package(pack_options->input, pack_options->output);
    print_text("wrote " + std::filesystem::absolute(pack_options->output).string() + "\n");
  });

  auto* unpack = app.add_subcommand("unpack", "Unzip a .vscz into a package folder");
  auto unpack_options = std::make_shared<Options>();
  unpack->add_option("archive", unpack_options->input, "Input .vscz")->required();
  unpack->add_option("-o,--output", unpack_options->output, "Output folder")->required();
  unpack->callback([unpack_options] {
    core::unpack_package(unpack_options->input, unpack_options->output);
    print_text("wrote " + std::filesystem::absolute(unpack_options->output).string() + "\n");
  });
}

}  // namespace viscera::cli
