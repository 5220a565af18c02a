#include "studio/document/variant_batch.h"

#include <set>

#include "core/error.h"
#include "core/random.h"
#include "simulator/dynamics/hydrometra_sweep.h"
#include "templates/generator/patient_seed.h"
#include "templates/generator/simulation_check.h"
#include "templates/generator/variant_generator.h"
#include "templates/variability/parameter_distribution.h"

namespace viscera::studio {
namespace {

const templates::ScenarioTemplate* catalogue_template(const std::string& name) {
  for (const auto& t : templates::template_catalog()) {
    if (t->name() == name) return t.get();
  }
  return nullptr;
}

/// The template's own rules; every other parameter fixed at the document's value.
std::vector<core::VariabilityRule> document_rules(const templates::ScenarioTemplate& t,
                                                  const core::Provenance& provenance) {
  std::vector<core::VariabilityRule> rules = t.default_variability();
  std::set<std::string> varied;
  for (const auto& rule : rules)
    varied.insert(rule.parameter);
  for (const auto& parameter : t.parameters()) {
    if (varied.contains(parameter.name)) continue;
    const auto value = provenance.parameters.find(parameter.name);
    if (value != provenance.parameters.end() && value->is_number())
      rules.push_back(templates::fixed_rule(parameter.name, value->get<double>()));
  }
  return rules;
}

Variant from_template(const core::Scenario& base, const VariantRequest& request, std::uint64_t k,
                      core::Progress& progress) {
  const templates::ScenarioTemplate* t = catalogue_template(base.provenance.template_name);
  if (t == nullptr || t->default_variability().empty())
    throw core::UsageError(
        "the document was not built from a catalogue template with variability rules, so it has "
        "no template variants; vary the scenario instead");
  templates::GenerationOptions options;
  options.max_attempts = request.max_attempts;
  options.validation = request.validation;
  options.simulate = request.simulate;
  const templates::VariantGenerator generator(*t, document_rules(*t, base.provenance), request.seed,
                                              options);
  Variant variant;
  variant.index = k;
  try {
    templates::GeneratedPatient patient = generator.generate(k, progress);
    variant.valid = true;
    variant.attempts = static_cast<int>(patient.redraws.size()) + 1;
    variant.draw_seed = patient.draw_seed;
    variant.validation = patient.validation.to_json();
    variant.scenario = std::move(patient.scenario);
  } catch (const core::ValidationError& e) {
    // Every draw failed: the generator names the last reason as "…; last: <check>: <detail>".
    const std::string message = e.what();
    const auto last = message.rfind("; last: ");
    variant.failure = last == std::string::npos ? message : message.substr(last + 8);
    variant.failed_check = variant.failure.substr(0, variant.failure.find(": "));
    variant.attempts = request.max_attempts;
    variant.draw_seed = templates::patient_seed(
        t->name(), request.seed, k, static_cast<std::uint64_t>(request.max_attempts - 1));
  }
  return variant;
}

Variant from_scenario(const core::Scenario& base, const VariantRequest& request, std::uint64_t k,
                      core::Progress& progress) {
  const std::string name = variant_source_name(base, VariantSource::Scenario);
  Variant variant;
  variant.index = k;
  for (int attempt = 0; attempt < request.max_attempts; ++attempt) {
    progress.check_cancelled();
    const std::uint64_t seed =
        templates::patient_seed(name, request.seed, k, static_cast<std::uint64_t>(attempt));
    core::Rng rng(seed);
    templates::ScenarioDraw draw = templates::vary_scenario(base, rng, request.variation);
    templates::PatientValidation validation =
        templates::validate_patient_geometry(draw.scenario, request.validation);
    if (validation.valid() && request.simulate)
      validation.checks.push_back(templates::simulate_one_second(draw.scenario));
    variant.attempts = attempt + 1;
    variant.draw_seed = seed;
    variant.valid = validation.valid();
    variant.failure = validation.first_failure();
    variant.failed_check = variant.failure.substr(0, variant.failure.find(": "));
    variant.validation = validation.to_json();
    variant.validation["drawn"] = draw.drawn;
    // Not the template's patient any more: the provenance names the variation instead.
    draw.scenario.provenance.template_name.clear();
    draw.scenario.provenance.template_version.clear();
    draw.scenario.provenance.seed = seed;
    draw.scenario.provenance.parameters = {{"source", "scenario-variation"},
                                           {"base", base.metadata.name},
                                           {"base_template", base.provenance.template_name},
                                           {"batch_seed", request.seed},
                                           {"index", k},
                                           {"drawn", draw.drawn}};
    draw.scenario.metadata.name =
        (base.metadata.name.empty() ? std::string("scenario") : base.metadata.name) + " variant " +
        std::to_string(k);
    // The variation moved the wall: its pressure states are computed again (seed 000 §2.1).
    if (variant.valid) sim::add_hydrometra_states(draw.scenario, core::Progress::none());
    variant.scenario = std::move(draw.scenario);
    if (variant.valid) break;
  }
  return variant;
}

}  // namespace

bool has_template_source(const core::Scenario& scenario) {
  const templates::ScenarioTemplate* t = catalogue_template(scenario.provenance.template_name);
  return t != nullptr && !t->default_variability().empty();
}

std::string variant_source_name(const core::Scenario& base, VariantSource source) {
  if (source == VariantSource::Template) return base.provenance.template_name;
  return "scenario:" + base.metadata.name;
}

Variant generate_variant(const core::Scenario& base, const VariantRequest& request, std::uint64_t k,
                         core::Progress& progress) {
  if (request.max_attempts < 1) throw core::UsageError("max attempts must be at least 1");
  return request.source == VariantSource::Template ? from_template(base, request, k, progress)
                                                   : from_scenario(base, request, k, progress);
}

std::vector<Variant> generate_variants(const core::Scenario& base, const VariantRequest& request,
                                       core::Progress& progress) {
  if (request.count < 1) throw core::UsageError("the number of variants must be at least 1");
  std::vector<Variant> variants;
  progress.begin_stage("generating variants", request.count);
  for (int k = 0; k < request.count; ++k) {
    variants.push_back(generate_variant(base, request, static_cast<std::uint64_t>(k), progress));
    progress.step();
  }
  return variants;
}

}  // namespace viscera::studio
