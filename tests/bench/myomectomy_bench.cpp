// The myomectomy session (issue 17 target: a 60 s myomectomy session ≥ 5× real time headless):
// the expert script data/scripts/hysteroscopy-myomectomy-expert.json (56.3 s: insertion, the
// myoma shaved in 14 strips, withdrawal) on `viscera new --template hysteroscopy-myomectomy
// --seed N`, N = the benchmark's argument, headless as `viscera-sim run --headless` runs it.
// Counters: real_time_factor = simulated / wall s, cuts, resected (fraction of myoma-1).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <fstream>

#include "simulator/dynamics/hydrometra_sweep.h"
#include "simulator/session/headless_session.h"
#include "simulator/session/instrument_input.h"
#include "templates/template_catalog.h"
#include "tests/bench/session_scripts.h"

namespace {

void BM_MyomectomySessionExpert(benchmark::State& state) {
  const auto seed = static_cast<std::uint64_t>(state.range(0));
  viscera::core::Scenario patient =
      viscera::templates::build_from_template("hysteroscopy-myomectomy", {}, seed);
  viscera::sim::add_hydrometra_states(patient);
  const std::string path =
      std::string(VISCERA_SOURCE_DIR) + "/data/scripts/hysteroscopy-myomectomy-expert.json";
  std::ifstream in(path);
  const auto json =
      viscera::sim::resolve_script_landmarks(nlohmann::json::parse(in), patient.landmarks, path);
  const auto input = viscera::sim::ScriptedTrajectory::from_json(json, path, 12.0);
  const auto options = viscera::bench::scripted_run(input, input.duration());
  double simulated = 0.0, wall = 0.0;
  for (auto _ : state) {
    const auto report = viscera::sim::run_headless(patient, options);
    simulated += report.simulated_time;
    wall += report.wall_time;
    if (report.cutting) {
      state.counters["cuts"] = report.cutting->cuts;
      const auto& bodies = report.cutting->bodies;
      const auto myoma = std::find_if(bodies.begin(), bodies.end(),
                                      [](const auto& b) { return b.body == "myoma-1"; });
      if (myoma != bodies.end()) state.counters["resected"] = myoma->resected_fraction();
    }
  }
  state.counters["real_time_factor"] = wall > 0.0 ? simulated / wall : 0.0;
}
BENCHMARK(BM_MyomectomySessionExpert)->DenseRange(1, 5)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
