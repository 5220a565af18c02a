#pragma once
/// The variant generator (issue 6 §3–4): turns one template and its variability rules into
/// validated virtual patients. Patient k of a batch is drawn from patient_seed(template, batch
/// seed, k, attempt) alone; a draw that fails to build or to validate is redrawn with the next
/// attempt, counted and reported, and never returned.

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/progress.h"
#include "core/scenario/scenario.h"
#include "templates/generator/simulation_check.h"
#include "templates/template_catalog.h"
#include "templates/validation/patient_validation.h"

namespace viscera::templates {

/// How hard the generator tries and what it checks.
struct GenerationOptions {
  int max_attempts = 25;  ///< draws per patient before the batch fails
  ValidationBounds validation;
  SimulationBounds simulation;
  bool simulate = true;  ///< run the simulated second (issue 6 §3)
};

/// One validated patient and how it was found.
struct GeneratedPatient {
  std::uint64_t index = 0;
  std::uint64_t draw_seed = 0;   ///< patient_seed of the accepted attempt
  std::uint64_t build_seed = 0;  ///< the seed the template built with (provenance seed)
  ParameterValues parameters;
  PatientValidation validation;  ///< every check of the accepted draw, all passed
  /// The rejected draws: {"attempt", "seed", "check", "reason"}.
  nlohmann::json redraws = nlohmann::json::array();
  core::Scenario scenario;
};

/// Generator for one batch: template, rules and batch seed.
class VariantGenerator {
 public:
  /// Checks `rules` against the template (check_rules). Throws core::UsageError.
  VariantGenerator(const ScenarioTemplate& scenario_template,
                   std::vector<core::VariabilityRule> rules, std::uint64_t batch_seed,
                   GenerationOptions options = {});

  /// Patient `k`: attempt a = 0, 1, … draws the parameters from Rng(patient_seed(…, k, a)),
  /// builds with that generator's next 64-bit output as the template seed, validates the
  /// geometry and simulates one second. Throws core::ValidationError after max_attempts
  /// failed draws (naming the last reason), core::CancelledError through `progress`.
  GeneratedPatient generate(std::uint64_t k,
                            core::Progress& progress = core::Progress::none()) const;

  const ScenarioTemplate& scenario_template() const { return template_; }
  const std::vector<core::VariabilityRule>& rules() const { return rules_; }
  std::uint64_t batch_seed() const { return batch_seed_; }
  const GenerationOptions& options() const { return options_; }

 private:
  const ScenarioTemplate& template_;
  std::vector<core::VariabilityRule> rules_;
  std::uint64_t batch_seed_;
  GenerationOptions options_;
};

/// Package folder name of patient k in a batch of `count`: "patient-0007.vscene" (at least
/// four digits, more when the batch needs them).
std::string patient_package_name(std::uint64_t k, std::uint64_t count);

/// The index record of a patient whose package is `package` (relative to the batch folder):
/// index, package, draw and build seeds, attempts, redraws, parameters, validation, the
/// primary organ's id and the counts of objects, pathologies, body nodes and tets.
nlohmann::json patient_record(const GeneratedPatient& patient, const std::string& package);

/// Generates patients `indices` of the batch of `count` and writes each package into `folder`
/// (created if missing); returns their records in the order of `indices`. Packages are written
/// atomically, so a failed or cancelled run leaves only complete patients.
nlohmann::json generate_share(const VariantGenerator& generator, std::uint64_t count,
                              const std::vector<std::uint64_t>& indices,
                              const std::filesystem::path& folder,
                              core::Progress& progress = core::Progress::none());

}  // namespace viscera::templates
