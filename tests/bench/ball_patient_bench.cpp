// How long the foundation's thin path takes to author a patient: template build (icosphere,
// gmsh tets, embedding) and package write/read.

#include <benchmark/benchmark.h>

#include <filesystem>

#include "core/package/scenario_package.h"
#include "templates/template_catalog.h"

namespace {

using viscera::templates::build_from_template;

void BM_BallTemplateBuild(benchmark::State& state) {
  const std::map<std::string, std::string> overrides = {
      {"cell_size", std::to_string(static_cast<double>(state.range(0)) * 1e-3)}};
  std::size_t tets = 0;
  for (auto _ : state) {
    const auto scenario = build_from_template("ball", overrides, 1);
    tets = scenario.objects[0].body.tets.size();
    benchmark::DoNotOptimize(tets);
  }
  state.counters["tets"] = static_cast<double>(tets);
  state.counters["tets_per_s"] =
      benchmark::Counter(static_cast<double>(tets), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_BallTemplateBuild)->Arg(8)->Arg(4)->Unit(benchmark::kMillisecond);

void BM_PackageWriteRead(benchmark::State& state) {
  const auto scenario = build_from_template("ball", {{"cell_size", "0.004"}}, 1);
  const auto dir = std::filesystem::temp_directory_path() / "viscera-bench-package";
  std::filesystem::create_directories(dir);
  const auto path = dir / (state.range(0) ? "ball.vscz" : "ball.vscene");
  for (auto _ : state) {
    viscera::core::write_package(scenario, path);
    const auto back = viscera::core::read_package(path);
    benchmark::DoNotOptimize(back.objects.size());
  }
  state.counters["tets"] = static_cast<double>(scenario.objects[0].body.tets.size());
  std::filesystem::remove_all(dir);
}
BENCHMARK(BM_PackageWriteRead)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
