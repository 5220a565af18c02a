#include "templates/template_catalog.h"

#include <charconv>
#include <cmath>

#include "core/error.h"
#include "core/version.h"
#include "templates/agent_tissue/agent_tissue_template.h"
#include "templates/ball_template.h"
#include "templates/hysteroscopy/hysteroscopy_template.h"
#include "templates/laparoscopy/laparoscopy_gyn_template.h"
#include "templates/urethra/urethra_template.h"

namespace viscera::templates {

const std::vector<std::unique_ptr<ScenarioTemplate>>& template_catalog() {
  static const std::vector<std::unique_ptr<ScenarioTemplate>> catalog = [] {
    std::vector<std::unique_ptr<ScenarioTemplate>> list;
    list.push_back(std::make_unique<BallTemplate>());
    list.push_back(std::make_unique<HysteroscopyTemplate>());
    list.push_back(std::make_unique<HysteroscopyTemplate>(HysteroscopyVariant::polypectomy));
    list.push_back(std::make_unique<HysteroscopyTemplate>(HysteroscopyVariant::myomectomy));
    list.push_back(std::make_unique<LaparoscopyGynTemplate>());
    list.push_back(std::make_unique<UrethraTemplate>());
    list.push_back(std::make_unique<AgentTissueTemplate>());
    return list;
  }();
  return catalog;
}

ParameterGroup parameter_group(const TemplateParameter& parameter) {
  const std::string& n = parameter.name;
  const auto has = [&n](const char* part) { return n.find(part) != std::string::npos; };
  if (n.starts_with("texture_")) return ParameterGroup::Texture;
  if (n.starts_with("vessel_") || has("artery") || n == "heart_rate")
    return ParameterGroup::Vessels;
  if (has("myoma") || has("polyp") || has("adhesion") || has("inclusion"))
    return ParameterGroup::Pathologies;
  if (has("stiffness") || has("damping") || n.starts_with("fixed_") || has("friction") ||
      has("strain") || has("break_") || n == "density" || n == "cell_mass" ||
      n == "max_displacement")
    return ParameterGroup::Tissue;
  if (n == "resolution" || n == "edge_length" || n == "cell_size" || n == "sections" ||
      n == "points_per_section" || n == "visual_subdivisions" || n == "spacing" || n == "columns" ||
      n == "rows")
    return ParameterGroup::Meshing;
  return ParameterGroup::Anatomy;
}

std::string to_string(ParameterGroup group) {
  switch (group) {
    case ParameterGroup::Anatomy:
      return "anatomy";
    case ParameterGroup::Pathologies:
      return "pathologies";
    case ParameterGroup::Tissue:
      return "tissue";
    case ParameterGroup::Vessels:
      return "vessels";
    case ParameterGroup::Texture:
      return "texture";
    case ParameterGroup::Meshing:
      return "meshing";
  }
  return "anatomy";
}

const ScenarioTemplate& find_template(const std::string& name) {
  std::string known;
  for (const auto& t : template_catalog()) {
    if (t->name() == name) return *t;
    known += (known.empty() ? "" : ", ") + t->name();
  }
  throw core::UsageError("unknown template \"" + name + "\"; known templates: " + known);
}

ParameterValues resolve_parameters(const ScenarioTemplate& scenario_template,
                                   const std::map<std::string, std::string>& overrides) {
  ParameterValues values;
  const auto parameters = scenario_template.parameters();
  for (const auto& p : parameters)
    values[p.name] = p.default_value;
  for (const auto& entry : overrides) {
    // Named, not a structured binding: clang 14 (the fuzz build) cannot capture one in a lambda.
    const std::string& name = entry.first;
    const std::string& text = entry.second;
    const auto it = std::find_if(parameters.begin(), parameters.end(),
                                 [&](const TemplateParameter& p) { return p.name == name; });
    if (it == parameters.end()) {
      throw core::UsageError("template \"" + scenario_template.name() + "\" has no parameter \"" +
                             name + "\"");
    }
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
      throw core::UsageError("parameter \"" + name + "\": \"" + text + "\" is not a number");
    }
    if (it->integer && value != std::floor(value)) {
      throw core::UsageError("parameter \"" + name + "\" must be a whole number");
    }
    if (value < it->minimum || value > it->maximum) {
      throw core::UsageError("parameter \"" + name + "\" = " + text + " is outside [" +
                             std::to_string(it->minimum) + ", " + std::to_string(it->maximum) +
                             "] " + it->unit);
    }
    values[name] = value;
  }
  return values;
}

nlohmann::json catalog_to_json() {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& t : template_catalog()) {
    nlohmann::json parameters = nlohmann::json::array();
    for (const auto& p : t->parameters()) {
      parameters.push_back({{"name", p.name},
                            {"unit", p.unit},
                            {"description", p.description},
                            {"minimum", p.minimum},
                            {"maximum", p.maximum},
                            {"default", p.default_value},
                            {"integer", p.integer},
                            {"group", to_string(parameter_group(p))}});
    }
    list.push_back({{"name", t->name()},
                    {"description", t->description()},
                    {"version", t->version()},
                    {"procedure", t->procedure()},
                    {"parameters", parameters}});
    if (nlohmann::json counts = t->reference_counts(); !counts.is_null())
      list.back()["reference_counts"] = std::move(counts);
  }
  return list;
}

core::Scenario build_from_template(const std::string& name,
                                   const std::map<std::string, std::string>& overrides,
                                   std::uint64_t seed, core::Progress& progress) {
  const ScenarioTemplate& scenario_template = find_template(name);
  const ParameterValues values = resolve_parameters(scenario_template, overrides);
  core::Scenario scenario = scenario_template.build(values, seed, progress);
  scenario.provenance.template_name = scenario_template.name();
  scenario.provenance.template_version = scenario_template.version();
  scenario.provenance.seed = seed;
  scenario.provenance.parameters = nlohmann::json(values);
  scenario.provenance.tool_versions = core::tool_versions();
  if (scenario.variability.empty()) scenario.variability = scenario_template.default_variability();
  return scenario;
}

}  // namespace viscera::templates
