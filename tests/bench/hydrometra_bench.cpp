// The hydrometra at run time (issue 18 target: ≤ 0.1 ms per step; seed 000 §2.1): the default
// hysteroscopy patient's uterus swept once into its 100 pressure states (the authoring step of
// `viscera new`), then per iteration what a session step does with a new pressure.
//   BM_HydrometraInterpolation: the states interpolated piecewise linearly at the pressure
//     (core::interpolate_hydrometra, every body node);
//   BM_HydrometraStep: HydrometraForces::set_pressure + prepare — the interpolation, the
//     target shape and the cavity's pressure load on it.
//   BM_HydrometraSweep: the authoring step itself (sim::sweep_hydrometra on that uterus).
// The pressure walks through the clinical range (a different bracket each iteration).

#include <benchmark/benchmark.h>

#include <memory>

#include "core/scenario/hydrometra_states.h"
#include "simulator/dynamics/cavity_pressure.h"
#include "simulator/dynamics/hydrometra_forces.h"
#include "simulator/dynamics/hydrometra_sweep.h"
#include "simulator/world/world.h"
#include "templates/template_catalog.h"

namespace {

using viscera::core::Vec3;

const viscera::core::Scenario& bare_patient() {
  static const viscera::core::Scenario scenario =
      viscera::templates::build_from_template("hysteroscopy", {}, 1);
  return scenario;
}

const viscera::core::Scenario& patient() {
  static const viscera::core::Scenario scenario = [] {
    viscera::core::Scenario s = bare_patient();
    viscera::sim::add_hydrometra_states(s);
    return s;
  }();
  return scenario;
}

void BM_HydrometraSweep(benchmark::State& state) {
  const viscera::core::Scenario& s = bare_patient();
  viscera::core::HydrometraStates states;
  for (auto _ : state) {
    states = viscera::sim::sweep_hydrometra(s.objects[0], s.materials);
    benchmark::DoNotOptimize(states.displacements.data());
  }
  state.counters["nodes"] = states.node_count;
  state.counters["top_pressure_Pa"] = states.pressures.back();
}
BENCHMARK(BM_HydrometraSweep)->Unit(benchmark::kMillisecond)->Iterations(3);

/// Pa: pressures spread over the states' range (never on a stored state).
double pressure_at(const viscera::core::HydrometraStates& states, std::int64_t i) {
  return states.pressures.back() * (0.5 + static_cast<double>((i * 7919) % 10007)) / 10008.0;
}

void BM_HydrometraInterpolation(benchmark::State& state) {
  const viscera::core::HydrometraStates& states = patient().objects[0].hydrometra;
  std::vector<Vec3> out(static_cast<std::size_t>(states.node_count));
  std::int64_t i = 0;
  for (auto _ : state) {
    viscera::core::interpolate_hydrometra(states, pressure_at(states, i++), out);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["nodes"] = states.node_count;
  state.counters["states"] = states.state_count();
}
BENCHMARK(BM_HydrometraInterpolation)->Unit(benchmark::kMicrosecond);

void BM_HydrometraStep(benchmark::State& state) {
  const viscera::core::Scenario& scenario = patient();
  viscera::sim::World world(scenario);
  const auto& model = world.models()[0];
  viscera::sim::HydrometraForces forces(model, world.state(), scenario.objects[0]);
  const viscera::sim::StepContext context{0.0, world.time_step(), 1};
  std::int64_t i = 0;
  for (auto _ : state) {
    forces.set_pressure(pressure_at(scenario.objects[0].hydrometra, i++));
    forces.prepare(world.state(), context);
    benchmark::DoNotOptimize(forces.loads().data());
  }
  state.counters["nodes"] = forces.states().node_count;
  state.counters["cavity_faces"] =
      static_cast<double>(viscera::sim::cavity_surface(scenario.objects[0]).faces.size());
}
BENCHMARK(BM_HydrometraStep)->Unit(benchmark::kMicrosecond);

}  // namespace
