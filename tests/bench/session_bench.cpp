// Headless training sessions on the hysteroscopy template (issue 8 point 9): a 10-minute session
// of the expert's tour (data/scripts/hysteroscopy-expert.json repeated, free navigation), the
// novice's 14.6 s session that bumps the wall, and the honest case for a training session:
// 10 minutes of the novice's pattern back to back, with its wall contacts. Counters:
// real_time_factor = simulated / wall s, contact_fraction = share of the path samples with the
// instrument on the wall, substeps per 1 ms step.

#include <benchmark/benchmark.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "simulator/session/headless_session.h"
#include "simulator/session/instrument_input.h"
#include "templates/template_catalog.h"

namespace {

const viscera::core::Scenario& patient() {
  static const viscera::core::Scenario scenario =
      viscera::templates::build_from_template("hysteroscopy", {}, 1);
  return scenario;
}

/// The script with its landmark places resolved on the patient.
nlohmann::json script(const std::string& who) {
  const std::string path =
      std::string(VISCERA_SOURCE_DIR) + "/data/scripts/hysteroscopy-" + who + ".json";
  std::ifstream in(path);
  return viscera::sim::resolve_script_landmarks(nlohmann::json::parse(in), patient().landmarks,
                                                path);
}

/// The script repeated back to back until `seconds`.
nlohmann::json repeated(nlohmann::json tour, double seconds) {
  const nlohmann::json once = tour["waypoints"];
  const double length = once.back()["t"].get<double>() + 0.5;
  nlohmann::json waypoints = nlohmann::json::array();
  for (double offset = 0.0; offset < seconds; offset += length) {
    for (auto point : once) {
      point["t"] = point["t"].get<double>() + offset;
      waypoints.push_back(point);
    }
  }
  tour["waypoints"] = waypoints;
  return tour;
}

void run(benchmark::State& state, const nlohmann::json& json, double duration) {
  const auto input = viscera::sim::ScriptedTrajectory::from_json(json, "script", 30.0);
  viscera::sim::HeadlessRunOptions options;
  options.duration = duration;
  options.instrument = &input;
  options.instrument_body = input.body();
  options.instrument_stiffness = input.stiffness();
  options.force_warning = input.force_warning();
  options.end_when_complete = false;  // the tour goes on after the procedure's tasks are done
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
