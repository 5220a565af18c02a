// Variant generation (issue 6 §6): validated hysteroscopy patients per minute on one core — draw,
// build (uterus, pathologies, gmsh bodies, CCO tree), geometric validation, one perturbed
// simulated second, package write — counting redraws as the generator does. On 2 cores the
// CLI runs two such processes under mpirun (tests/bench/generate_mpi_efficiency.sh measures their
// efficiency; docs/performance.md).

#include <benchmark/benchmark.h>

#include <filesystem>

#include "templates/generator/variant_generator.h"

namespace {

using namespace viscera::templates;

void BM_GenerateHysteroscopyPatient(benchmark::State& state) {
  const ScenarioTemplate& t = find_template("hysteroscopy");
  const VariantGenerator generator(t, t.default_variability(), 1);
  const auto dir = std::filesystem::temp_directory_path() / "viscera-bench-generate";
  std::filesystem::remove_all(dir);
  std::uint64_t k = 0, redraws = 0;
  for (auto _ : state) {
    // A new patient every iteration: patients differ in size and pathologies, and the rate is
    // over the batch, not one favourable draw.
    const nlohmann::json records = generate_share(generator, 1000000, {k}, dir);
    redraws += records[0].at("redraws").size();
    ++k;
  }
  std::filesystem::remove_all(dir);
  // Patients per second of wall time (× 60 for per minute); CPU time per patient is the
  // benchmark's own CPU column.
  state.counters["patients"] =
      benchmark::Counter(static_cast<double>(k), benchmark::Counter::kIsRate);
  state.counters["redraws_per_patient"] =
      static_cast<double>(redraws) / static_cast<double>(std::max<std::uint64_t>(k, 1));
}
BENCHMARK(BM_GenerateHysteroscopyPatient)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(10)
    ->UseRealTime();

}  // namespace
