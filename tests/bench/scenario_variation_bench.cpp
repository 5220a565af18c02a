// Scenario variants as the studio's "Generate variants…" draws them for a document without a
// template (templates/variability/scenario_variation.h): one smooth deformation of the whole
// scene and re-drawn pathology sizes, then the geometric patient validation. Measured on a
// hysteroscopy patient (uterus with layers, myoma, vessel tree) treated as an arbitrary scenario.

#include <benchmark/benchmark.h>

#include "core/random.h"
#include "templates/template_catalog.h"
#include "templates/validation/patient_validation.h"
#include "templates/variability/scenario_variation.h"

namespace {

using namespace viscera;

void BM_VaryAndValidateScenario(benchmark::State& state) {
  const core::Scenario base = templates::build_from_template("hysteroscopy", {}, 1);
  std::uint64_t seed = 0, valid = 0;
  for (auto _ : state) {
    core::Rng rng(++seed);
    const templates::ScenarioDraw draw = templates::vary_scenario(base, rng);
    valid += templates::validate_patient_geometry(draw.scenario).valid() ? 1 : 0;
  }
  state.counters["variants"] =
      benchmark::Counter(static_cast<double>(seed), benchmark::Counter::kIsRate);
  state.counters["valid_share"] = static_cast<double>(valid) / static_cast<double>(seed);
}
BENCHMARK(BM_VaryAndValidateScenario)->Unit(benchmark::kMillisecond)->Iterations(10)->UseRealTime();

}  // namespace
