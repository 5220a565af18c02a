#pragma once
/// "Generate variants…" of the studio (issue 9 §6), without widgets: N virtual patients from the
/// current document, drawn with the same library as `viscera generate`.
///
/// Two sources, chosen by the user where both apply:
/// - Template: the document was built from a catalogue template with variability rules (its
///   provenance names the template and its parameters). The template's VariantGenerator draws each
///   patient: the template's default variability rules vary, every other parameter stays fixed at
///   the document's value. Edits made to the document after it was built are not in these variants
///   (they are rebuilt from the template).
/// - Scenario: any document, e.g. an organ meshed from an image volume. Each draw is
///   vary_scenario (templates/variability/scenario_variation.h): one smooth random deformation
///   of the whole scene and re-drawn pathology sizes, validated by validate_patient_geometry and,
///   when asked, the simulated second.
/// Patient k's draw a uses patient_seed(name, seed, k, a) in both — name the template's, or
/// "scenario:<metadata name>" — so a variant does not depend on N or on the others. An invalid
/// draw is redrawn up to max_attempts times; a variant that never passes is returned as failed
/// with its last failing check (and, for the scenario source, that last draw, to inspect).
/// A scenario variant's provenance names no template: its seed is the draw's and its parameters
/// {"source": "scenario-variation", "base", "base_template", "batch_seed", "index", "drawn"}.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/progress.h"
#include "core/scenario/scenario.h"
#include "templates/validation/patient_validation.h"
#include "templates/variability/scenario_variation.h"

namespace viscera::studio {

enum class VariantSource { Template, Scenario };

/// What to generate.
struct VariantRequest {
  int count = 8;
  std::uint64_t seed = 1;
  VariantSource source = VariantSource::Scenario;
  int max_attempts = 5;   ///< draws per variant before it counts as failed
  bool simulate = false;  ///< also run the simulated second (templates/generator)
  templates::ValidationBounds validation;
  templates::ScenarioVariation variation;  ///< the scenario source only
};

/// One generated variant.
struct Variant {
  std::uint64_t index = 0;
  bool valid = false;
  int attempts = 0;             ///< draws made (1 = the first was valid)
  std::string failed_check;     ///< e.g. "overlap"; empty when valid
  std::string failure;          ///< "check: detail" of the last rejected draw; empty when valid
  std::uint64_t draw_seed = 0;  ///< patient_seed of the returned draw
  nlohmann::json validation;    ///< PatientValidation::to_json of the returned draw, or null
  std::optional<core::Scenario> scenario;  ///< absent when no draw could be built
};

/// True when `scenario`'s provenance names a catalogue template that has variability rules (the
/// Template source applies); a template without rules (ball) would give N copies of one patient,
/// so its documents vary as scenarios.
bool has_template_source(const core::Scenario& scenario);

/// The source name used for the seeds: the template's name or "scenario:<metadata name>".
std::string variant_source_name(const core::Scenario& base, VariantSource source);

/// Variant k of `base`. Throws core::UsageError for a bad request (count < 1, max_attempts < 1,
/// a Template source without a template), core::CancelledError through `progress`.
Variant generate_variant(const core::Scenario& base, const VariantRequest& request, std::uint64_t k,
                         core::Progress& progress = core::Progress::none());

/// Variants 0 … count−1, one progress step each ("generating variants").
std::vector<Variant> generate_variants(const core::Scenario& base, const VariantRequest& request,
                                       core::Progress& progress = core::Progress::none());

}  // namespace viscera::studio
