// The laparoscopy-gyn scene of seed 001 (21 KisMo nets) in a session (issue 19 target: ≥ 1 kHz
// physics headless with pulse, motility and tools): its arteries pulse and its sigmoid moves,
// and the laparoscope's working port carries the grasper of the shipped expert sterilisation
// script — the first 8 s: both tubes located, the isthmus grasped and pulled; and its first 12 s,
// with the second port's grasper holding the tube during two bipolar bites. Counters:
// physics_rate_hz = physics steps per wall-clock second, real_time_factor = simulated / wall s,
// substeps per 1 ms step. Also the scene awake without an instrument (pulse and motility only).

#include <benchmark/benchmark.h>

#include "core/json_text.h"
#include "simulator/session/headless_session.h"
#include "simulator/session/instrument_input.h"
#include "templates/template_catalog.h"
#include "tests/bench/session_scripts.h"

namespace {

const viscera::core::Scenario& patient() {
  static const viscera::core::Scenario s =
      viscera::templates::build_from_template("laparoscopy-gyn", {}, 1);
  return s;
}

/// Runs the session once per iteration and reports its rates.
void run(benchmark::State& state, const viscera::sim::HeadlessRunOptions& options) {
  double simulated = 0.0, wall = 0.0;
  viscera::sim::SessionReport report;
  for (auto _ : state) {
    report = viscera::sim::run_headless(patient(), options);
    simulated += report.simulated_time;
    wall += report.wall_time;
  }
  state.counters["substeps"] = report.substeps;
  state.counters["real_time_factor"] = wall > 0.0 ? simulated / wall : 0.0;
  state.counters["physics_rate_hz"] = wall > 0.0 ? simulated / report.time_step / wall : 0.0;
}

/// The shipped expert sterilisation.
const viscera::sim::ScriptedTrajectory& expert() {
  static const viscera::sim::ScriptedTrajectory script = [] {
    const std::string file =
        std::string(VISCERA_SOURCE_DIR) + "/data/scripts/laparoscopy-sterilisation-expert.json";
    const auto json = viscera::sim::resolve_script_landmarks(viscera::core::read_json_file(file),
                                                             patient().landmarks, file);
    return viscera::sim::ScriptedTrajectory::from_json(json, file, 30.0);
  }();
  return script;
}

void BM_LaparoscopySceneGrasping(benchmark::State& state) {
  run(state, viscera::bench::scripted_run(expert(), 8.0));
}
BENCHMARK(BM_LaparoscopySceneGrasping)->Iterations(1)->Unit(benchmark::kSecond);

/// The expert's first 12 s: after the right hand's grasp, the left hand's grasper comes in
/// through the second port (8.4 s) and holds the tube (9.3 s) while the right hand's bipolar
/// forceps take the first two bites with their smoke — two tools in the tissue at once.
void BM_LaparoscopySceneTwoTools(benchmark::State& state) {
  run(state, viscera::bench::scripted_run(expert(), 12.0));
}
BENCHMARK(BM_LaparoscopySceneTwoTools)->Iterations(1)->Unit(benchmark::kSecond);

void BM_LaparoscopySceneAwake(benchmark::State& state) {
  viscera::sim::HeadlessRunOptions options;
  options.duration = 4.0;
  run(state, options);
}
BENCHMARK(BM_LaparoscopySceneAwake)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
