// Headless training sessions on the hysteroscopy template (issue 8 point 9): a 10-minute session
// of the expert's tour (data/scripts/hysteroscopy-expert.json repeated, free navigation), the
// novice's 14.6 s session that bumps the wall, and the honest case for a training session:
// 10 minutes of the novice's pattern back to back, with its wall contacts. Counters:
// real_time_factor = simulated / wall s, contact_fraction = share of the path samples with the
// instrument on the wall, substeps per 1 ms step.

#include <benchmark/benchmark.h>

#include "simulator/session/headless_session.h"
#include "simulator/session/instrument_input.h"
#include "templates/template_catalog.h"
#include "tests/bench/session_scripts.h"

namespace {

using viscera::bench::repeated;

const viscera::core::Scenario& patient() {
  return viscera::bench::hysteroscopy_patient();
}
nlohmann::json script(const std::string& who) {
  return viscera::bench::hysteroscopy_script(who);
}

void run(benchmark::State& state, const nlohmann::json& json, double duration) {
  const auto input = viscera::sim::ScriptedTrajectory::from_json(json, "script", 30.0);
  const auto options = viscera::bench::scripted_run(input, duration);
  double simulated = 0.0, wall = 0.0;
  for (auto _ : state) {
    const auto report = viscera::sim::run_headless(patient(), options);
    simulated += report.simulated_time;
    wall += report.wall_time;
    state.counters["contacts"] = report.metrics.contacts();
    state.counters["substeps"] = report.substeps;
    long long touching = 0;
    for (const auto& sample : report.path)
      touching += sample.in_contact ? 1 : 0;
    state.counters["contact_fraction"] =
        report.path.empty()
            ? 0.0
            : static_cast<double>(touching) / static_cast<double>(report.path.size());
  }
  state.counters["real_time_factor"] = wall > 0.0 ? simulated / wall : 0.0;
}

void BM_HysteroscopySessionExpert10min(benchmark::State& state) {
  run(state, repeated(script("expert"), 600.0), 600.0);
}
BENCHMARK(BM_HysteroscopySessionExpert10min)->Iterations(1)->Unit(benchmark::kSecond);

void BM_HysteroscopySessionNovicePressing(benchmark::State& state) {
  const auto json = script("novice");
  run(state, json, json["waypoints"].back()["t"].get<double>());
}
BENCHMARK(BM_HysteroscopySessionNovicePressing)->Iterations(1)->Unit(benchmark::kSecond);

void BM_HysteroscopySessionNovice10min(benchmark::State& state) {
  run(state, repeated(script("novice"), 600.0), 600.0);
}
BENCHMARK(BM_HysteroscopySessionNovice10min)->Iterations(1)->Unit(benchmark::kSecond);

/// The `ball` demo: the default ball template resting on its held base for 2 s, headless, no
/// instrument (what `./dev.sh demo` runs). real_time_factor = simulated / wall s.
void BM_BallDemoSession(benchmark::State& state) {
  const viscera::core::Scenario ball = viscera::templates::build_from_template("ball", {}, 1);
  viscera::sim::HeadlessRunOptions options;
  options.duration = 2.0;
  double simulated = 0.0, wall = 0.0;
  for (auto _ : state) {
    const auto report = viscera::sim::run_headless(ball, options);
    simulated += report.simulated_time;
    wall += report.wall_time;
    state.counters["substeps"] = report.substeps;
  }
  state.counters["real_time_factor"] = wall > 0.0 ? simulated / wall : 0.0;
}
BENCHMARK(BM_BallDemoSession)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
