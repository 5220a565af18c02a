// The distension flow step (issue 18 §2 targets: 40³ ≤ 2 ms and 64³ ≤ 8 ms on 2 cores; HystSim,
// seed 000 §2.2: 38 ms at 40³ on three CPUs). A cubic cavity of water walled all round, a jet
// from a 2×2-cell inflow on one wall at 0.2 m/s and an outflow opposite, MacCormack advection,
// projection to |∇·u| ≤ 1e-3 /s, 1 mm cells, Δt = 10 ms, after 30 steps of spin-up.

#include <benchmark/benchmark.h>

#include "simulator/fluid/stable_fluids.h"
#include "tests/support/walled_flow_box.h"

using namespace viscera::sim::fluid;

namespace {

FlowGrid jet_cavity(int n) {
  FlowGrid grid = viscera::test::walled_flow_box(n, n, n, 0.001);
  const int m = n / 2;
  for (int dj = 0; dj < 2; ++dj)
    for (int dk = 0; dk < 2; ++dk) {
      grid.set_cell(0, m + dj, m + dk, FlowCell::Solid, viscera::core::Vec3(0.2, 0.0, 0.0));
      grid.set_cell(n - 1, m / 2 + dj, m + dk, FlowCell::Open);
    }
  grid.update_faces();
  return grid;
}

void BM_FlowStep(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  FlowGrid grid = jet_cavity(n);
  FlowSettings settings;
  settings.viscosity = 1e-6;
  settings.time_step = 0.01;
  settings.divergence_tolerance = 1e-3;
  settings.threads = static_cast<int>(state.range(1));
  FlowSolver solver;
  for (int s = 0; s < 30; ++s)
    solver.step(grid, settings);
  long long iterations = 0, diffusion = 0, steps = 0;
  for (auto _ : state) {
    const FlowStepReport report = solver.step(grid, settings);
    iterations += report.pressure_iterations;
    diffusion += report.diffusion_iterations;
    ++steps;
    benchmark::DoNotOptimize(report);
  }
  state.counters["cells"] = static_cast<double>(n) * n * n;
  state.counters["pressure_iterations"] = static_cast<double>(iterations) / steps;
  state.counters["diffusion_iterations"] = static_cast<double>(diffusion) / steps;
}

}  // namespace

BENCHMARK(BM_FlowStep)->Args({40, 1})->Args({40, 2})->Args({64, 2})->Unit(benchmark::kMillisecond);
