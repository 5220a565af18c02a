#include "templates/generator/variant_generator.h"

#include <algorithm>
#include <map>

#include "core/error.h"
#include "core/log.h"
#include "core/package/scenario_package.h"
#include "core/random.h"
#include "core/version.h"
#include "simulator/dynamics/hydrometra_sweep.h"
#include "templates/generator/batch_share.h"
#include "templates/generator/patient_seed.h"
#include "templates/variability/parameter_distribution.h"

namespace viscera::templates {

VariantGenerator::VariantGenerator(const ScenarioTemplate& scenario_template,
                                   std::vector<core::VariabilityRule> rules,
                                   std::uint64_t batch_seed, GenerationOptions options)
    : template_(scenario_template),
      rules_(std::move(rules)),
      batch_seed_(batch_seed),
      options_(options) {
  check_rules(template_, rules_);
  if (options_.max_attempts < 1) throw core::UsageError("max_attempts must be at least 1");
}

GeneratedPatient VariantGenerator::generate(std::uint64_t k, core::Progress& progress) const {
  GeneratedPatient patient;
  patient.index = k;
  std::string last_reason;
  for (int attempt = 0; attempt < options_.max_attempts; ++attempt) {
    progress.check_cancelled();
    const std::uint64_t seed =
        patient_seed(template_.name(), batch_seed_, k, static_cast<std::uint64_t>(attempt));
    core::Rng rng(seed);
    const ParameterValues parameters = draw_parameters(template_, rules_, rng);
    const std::uint64_t build_seed = rng.next_u64();
    const auto reject = [&](const std::string& check, const std::string& reason) {
      patient.redraws.push_back(
          {{"attempt", attempt}, {"seed", seed}, {"check", check}, {"reason", reason}});
      last_reason = check + ": " + reason;
      core::logger()->info("patient {} draw {} rejected: {}", k, attempt, last_reason);
    };
    core::Scenario scenario;
    try {
      scenario = template_.build(parameters, build_seed, core::Progress::none());
    } catch (const core::CancelledError&) {
      throw;
    } catch (const core::Error& e) {
      // A draw the template cannot build (no room for a pathology, a surface gmsh refuses)
      // is an invalid draw like any other.
      reject("build", e.what());
      continue;
    }
    PatientValidation validation = validate_patient_geometry(scenario, options_.validation);
    if (validation.valid() && options_.simulate)
      validation.checks.push_back(simulate_one_second(scenario, options_.simulation));
    if (!validation.valid()) {
      const std::string failure = validation.first_failure();
      const auto colon = failure.find(": ");
      reject(failure.substr(0, colon), failure.substr(colon + 2));
      continue;
    }
    // Pipeline step of every valid patient: the cavity's pressure states (seed 000 §2.1),
    // without stages of its own (the batch's progress counts patients, as build() above).
    sim::add_hydrometra_states(scenario, core::Progress::none());
    scenario.provenance.template_name = template_.name();
    scenario.provenance.template_version = template_.version();
    scenario.provenance.seed = build_seed;
    scenario.provenance.parameters = nlohmann::json(parameters);
    scenario.provenance.tool_versions = core::tool_versions();
    scenario.variability = rules_;
    patient.draw_seed = seed;
    patient.build_seed = build_seed;
    patient.parameters = parameters;
    patient.validation = std::move(validation);
    patient.scenario = std::move(scenario);
    return patient;
  }
  std::map<std::string, int> by_check;
  for (const auto& r : patient.redraws)
    ++by_check[r.at("check").get<std::string>()];
  std::string counts;
  for (const auto& [check, n] : by_check)
    counts += (counts.empty() ? "" : ", ") + check + " " + std::to_string(n);
  throw core::ValidationError("patient " + std::to_string(k) + " of template " + template_.name() +
                              " failed validation in all " + std::to_string(options_.max_attempts) +
                              " draws (" + counts + "); last: " + last_reason);
}

std::string patient_package_name(std::uint64_t k, std::uint64_t count) {
  const std::size_t digits =
      std::max<std::size_t>(4, std::to_string(count > 0 ? count - 1 : 0).size());
  std::string number = std::to_string(k);
  if (number.size() < digits) number.insert(0, digits - number.size(), '0');
  return "patient-" + number + ".vscene";
}

nlohmann::json patient_record(const GeneratedPatient& patient, const std::string& package) {
  const core::Scenario& s = patient.scenario;
  std::string organ;
  std::size_t nodes = 0, tets = 0;
  for (const auto& o : s.objects) {
    if (organ.empty() && o.role == core::ObjectRole::Organ) organ = o.id;
    nodes += o.body.nodes.size();
    tets += o.body.tets.size();
  }
  nlohmann::json kinds = nlohmann::json::array();
  for (const auto& p : s.pathologies)
    kinds.push_back(p.kind);
  return {{"index", patient.index},
          {"package", package},
          {"draw_seed", patient.draw_seed},
          {"seed", patient.build_seed},
          {"attempts", patient.redraws.size() + 1},
          {"redraws", patient.redraws},
          {"parameters", patient.parameters},
          {"validation", patient.validation.to_json()},
          {"organ", organ},
          {"objects", s.objects.size()},
          {"pathologies", kinds},
          {"body_nodes", nodes},
          {"body_tets", tets}};
}

nlohmann::json generate_share(const VariantGenerator& generator, std::uint64_t count,
                              const std::vector<std::uint64_t>& indices,
                              const std::filesystem::path& folder, core::Progress& progress) {
  return generate_patients(generator, count, indices, local_positions(indices.size()), folder,
                           nullptr, progress)
      .records;
}

}  // namespace viscera::templates
