#include "studio/cli/material_commands.h"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/error.h"
#include "core/materials/cubic_stress_fit.h"
#include "core/materials/material_constants.h"
#include "core/materials/material_file.h"
#include "core/materials/shipped_materials.h"
#include "core/materials/stress_strain_csv.h"
#include "core/scenario/scenario_json.h"
#include "studio/cli/command_output.h"
#include "textures/png_io.h"

namespace viscera::cli {
namespace {

namespace fs = std::filesystem;

struct FitOptions {
  std::string csv, output, id, name, base;
  double poisson = 0.45, working_strain = 0.0, membrane = 0.0;
  double density = 0.0, damping = -1.0, tearing = 0.0, yield = 0.0;
  bool json = false;
};

void fit(const FitOptions& o) {
  const core::StressStrainCurve curve = core::read_stress_strain_csv(o.csv);
  core::Material base = o.base.empty() ? core::Material{} : core::shipped_material(o.base);
  base.id = o.id.empty() ? fs::path(o.csv).stem().string() : o.id;
  base.name = o.name.empty() ? base.id : o.name;
  if (o.density > 0.0) base.density = o.density;
  if (o.damping >= 0.0) base.distance_damping = o.damping;
  if (o.tearing > 0.0) base.tearing_threshold = o.tearing;
  if (o.yield > 0.0) base.plastic_yield = o.yield;
  core::ElasticityOptions elasticity;
  elasticity.poisson_ratio = o.poisson;
  elasticity.working_strain = o.working_strain;
  elasticity.membrane_thickness = o.membrane;

  const core::CubicStressFit fit = core::fit_cubic_stress(curve);
  const double working = o.working_strain > 0.0 ? o.working_strain : fit.max_strain;
  const core::TeschnerConstants constants =
      core::teschner_constants(fit.cubic, working, elasticity);
  core::Material material = core::material_from_measured_curve(curve, elasticity, base);
  std::ostringstream source;
  source << "cubic fitted to " << fs::path(o.csv).filename().string() << " (" << curve.strain.size()
         << " samples, RMS error " << fit.rms_error << " Pa); "
         << "Teschner constants at working strain " << working << ", Poisson ratio " << o.poisson;
  if (!o.base.empty()) source << "; other constants of shipped " << o.base << ": " << base.source;
  material.source = source.str();

  const nlohmann::json report = {{"csv", fs::path(o.csv).filename().string()},
                                 {"samples", curve.strain.size()},
                                 {"cubic", fit.cubic},
                                 {"rms_error", fit.rms_error},
                                 {"max_error", fit.max_error},
                                 {"max_error_sample", fit.max_error_sample},
                                 {"r_squared", fit.r_squared},
                                 {"max_strain", fit.max_strain},
                                 {"working_strain", constants.working_strain},
                                 {"linear_modulus", constants.linear_modulus},
                                 {"shear_modulus", constants.shear_modulus},
                                 {"lame_lambda", constants.lame_lambda},
                                 {"poisson_ratio", o.poisson}};
  textures::write_file_atomically(core::material_file_json(material, report).dump(2) + "\n",
                                  o.output);
  if (o.json) {
    print_json({{"material", fs::absolute(o.output).string()},
                {"id", material.id},
                {"fit", report},
                {"distance_stiffness", material.distance_stiffness},
                {"volume_stiffness", material.volume_stiffness},
                {"area_stiffness", material.area_stiffness}});
    return;
  }
  std::ostringstream out;
  out << "wrote " << fs::absolute(o.output).string() << "\n"
      << "  sigma(e) = " << fit.cubic[1] << " e + " << fit.cubic[2] << " e|e| + " << fit.cubic[3]
      << " e^3 Pa\n"
      << "  fit error  RMS " << fit.rms_error << " Pa, max " << fit.max_error << " Pa (sample "
      << fit.max_error_sample << "), R^2 " << fit.r_squared << "\n"
      << "  E " << constants.linear_modulus << " Pa at working strain " << working << "\n"
      << "  distance_stiffness " << material.distance_stiffness << " Pa, volume_stiffness "
      << material.volume_stiffness << " Pa, area_stiffness " << material.area_stiffness << " N/m\n";
  print_text(out.str());
}

void list_shipped(bool json) {
  if (json) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& shipped : core::shipped_materials()) {
      nlohmann::json sources = nlohmann::json::object();
      for (const auto& [quantity, source] : shipped.sources)
        sources[quantity] = source;
      list.push_back({{"material", shipped.material}, {"sources", sources}});
    }
    print_json(list);
    return;
  }
  std::ostringstream out;
  for (const auto& shipped : core::shipped_materials()) {
    const auto& m = shipped.material;
    out << m.id << "  " << m.name << "  density " << m.density << " kg/m^3, distance_stiffness "
        << m.distance_stiffness << " Pa, tearing strain " << m.tearing_threshold << "\n";
  }
  print_text(out.str());
}

void write_shipped(const std::string& id, const std::string& output) {
  const core::ShippedMaterial* shipped = core::find_shipped_material(id);
  if (shipped == nullptr) core::shipped_material(id);  // throws naming the known ids
  nlohmann::json sources = nlohmann::json::object();
  for (const auto& [quantity, source] : shipped->sources)
    sources[quantity] = source;
  textures::write_file_atomically(
      core::material_file_json(shipped->material, {{"sources", sources}}).dump(2) + "\n", output);
  print_text("wrote " + fs::absolute(output).string() + "\n");
}

}  // namespace

void add_material_commands(CLI::App& app) {
  auto* material = app.add_subcommand("material", "Tissue materials: fit measured curves");
  material->require_subcommand(1);

  auto o = std::make_shared<FitOptions>();
  auto* fit_command = material->add_subcommand(
      "fit", "Fit a cubic to a stress-strain CSV and derive the simulator's constants");
  fit_command->add_option("csv", o->csv, "Stress-strain CSV (strain, stress in Pa)")->required();
  fit_command->add_option("-o,--output", o->output, "Output material JSON")->required();
  fit_command->add_option("--id", o->id, "Material id (default: the CSV's stem)");
  fit_command->add_option("--name", o->name, "Material name");
  fit_command->add_option("--base", o->base,
                          "Shipped material whose density, damping, tearing and yield to keep");
  fit_command->add_option("--poisson", o->poisson, "Poisson ratio in [0.25, 0.5)")
      ->capture_default_str();
  fit_command->add_option("--working-strain", o->working_strain,
                          "Strain of the linearisation (default: the largest measured)");
  fit_command->add_option("--membrane-thickness", o->membrane,
                          "m of a surface membrane, for area stiffness");
  fit_command->add_option("--density", o->density, "kg/m^3");
  fit_command->add_option("--damping", o->damping, "Distance damping in Pa*s");
  fit_command->add_option("--tearing", o->tearing, "Tearing strain");
  fit_command->add_option("--yield", o->yield, "Plastic yield strain");
  fit_command->add_flag("--json", o->json, "Print JSON");
  fit_command->callback([o] { fit(*o); });

  auto list_json = std::make_shared<bool>(false);
  auto* list_command = material->add_subcommand("list", "List the shipped tissue materials");
  list_command->add_flag("--json", *list_json, "Print JSON with every number's source");
  list_command->callback([list_json] { list_shipped(*list_json); });

  auto shipped = std::make_shared<std::pair<std::string, std::string>>();
  auto* get_command = material->add_subcommand("get", "Write a shipped material as a JSON file");
  get_command->add_option("id", shipped->first, "Shipped material id")->required();
  get_command->add_option("-o,--output", shipped->second, "Output material JSON")->required();
  get_command->callback([shipped] { write_shipped(shipped->first, shipped->second); });
}

}  // namespace viscera::cli
