#pragma once
/// Scenario templates: deterministic functions (parameters, seed) → Scenario, and the catalogue
/// that `viscera templates` lists and `viscera new` builds from (DESIGN.md §9).

#include <cstdint>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/progress.h"
#include "core/scenario/scenario.h"

namespace viscera::templates {

/// One numeric parameter of a template, with its unit, range and default.
struct TemplateParameter {
  std::string name;
  std::string unit;  ///< SI unit, "1" for dimensionless, "count" for integers
  std::string description;
  double minimum = 0.0;
  double maximum = 0.0;
  double default_value = 0.0;
  bool integer = false;
};

/// Where a parameter belongs in a form (the studio's New from template dialog groups by it).
enum class ParameterGroup { Anatomy, Pathologies, Tissue, Vessels, Texture, Meshing };

/// The group of a catalogue parameter, from its name: stiffness, damping, friction and strain
/// limits are tissue; counts and sizes of lesions (myomas, polyps, adhesions, inclusions) are
/// pathologies; vessel_* are vessels; texture_* are texture; resolution, edge and cell sizes and
/// section counts are meshing; every other dimension is anatomy.
ParameterGroup parameter_group(const TemplateParameter& parameter);
/// "anatomy", "pathologies", "tissue", "vessels", "texture", "meshing".
std::string to_string(ParameterGroup group);

/// Parameter values by name; every parameter of the template is present after resolution.
using ParameterValues = std::map<std::string, double>;

/// A parametric scenario template.
class ScenarioTemplate {
 public:
  virtual ~ScenarioTemplate() = default;

  virtual std::string name() const = 0;
  virtual std::string description() const = 0;
  virtual std::string version() const = 0;
  /// The procedure the built scenario is set up for (see core::kProcedures).
  virtual std::string procedure() const = 0;
  virtual std::vector<TemplateParameter> parameters() const = 0;
  /// The template's own variability rules (variability/parameter_distribution.h): what a batch
  /// of patients varies by default. Parameters without a rule keep their default.
  virtual std::vector<core::VariabilityRule> default_variability() const { return {}; }

  /// Counts that tie the template to its source paper (e.g. knots and springs per model next
  /// to seed 001's table), listed by `viscera templates --json`; null when there are none.
  virtual nlohmann::json reference_counts() const { return nullptr; }

  /// Builds a scenario from fully resolved parameters; the same (parameters, seed) give the
  /// same scenario. Throws core::Error subclasses; CancelledError through `progress`.
  virtual core::Scenario build(const ParameterValues& parameters, std::uint64_t seed,
                               core::Progress& progress) const = 0;
};

/// Every built-in template, in a stable order.
const std::vector<std::unique_ptr<ScenarioTemplate>>& template_catalog();

/// The template named `name`; throws core::UsageError listing the known names otherwise.
const ScenarioTemplate& find_template(const std::string& name);

/// Defaults overridden by `overrides` ("name" → text value). Throws core::UsageError naming
/// the parameter for unknown names, unparsable numbers, non-integers for integer parameters
/// and values outside [minimum, maximum].
ParameterValues resolve_parameters(const ScenarioTemplate& scenario_template,
                                   const std::map<std::string, std::string>& overrides);

/// The catalogue as JSON: [{name, description, version, procedure, parameters:[…]}]; each
/// parameter carries its group (parameter_group).
nlohmann::json catalog_to_json();

/// Builds `name` with `overrides` and `seed`, and records the provenance (template, version,
/// seed, parameters, tool versions) in the scenario.
core::Scenario build_from_template(const std::string& name,
                                   const std::map<std::string, std::string>& overrides,
                                   std::uint64_t seed,
                                   core::Progress& progress = core::Progress::none());

}  // namespace viscera::templates
