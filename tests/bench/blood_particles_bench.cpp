// Blood particles (issue 18 target: 10,000 particles advected and emitted ≤ 1 ms). A 40³ cavity
// of 1 mm cells with a swirling flow; a source emits 0.2 µl particles at 1 ml/s (the Poiseuille
// rate of a cut 0.3 mm artery into an empty cavity is about that) with a 2 s life: 10,000 live
// in the steady state, which 2.5 s of 1 ms steps reach before timing. Each timed step emits what
// 1 ms bleeds (five particles), advances every particle in the flow, releases its blood into the
// concentration field and retires the oldest.

#include <benchmark/benchmark.h>

#include <cmath>

#include "simulator/fluid/blood_particles.h"

using namespace viscera;
using namespace viscera::sim::fluid;

namespace {

/// A 40³ grid whose x faces carry a swirl about the z axis and whose y faces carry its partner.
FlowGrid swirl(int n) {
  FlowGrid grid(n, n, n, 0.001);
  grid.update_faces();
  const double h = grid.cell_size(), centre = 0.5 * n * h;
  for (int axis = 0; axis < 2; ++axis) {
    const FaceDims d = grid.face_dims(axis);
    for (int k = 0; k < d.z; ++k)
      for (int j = 0; j < d.y; ++j)
        for (int i = 0; i < d.x; ++i) {
          const core::Vec3 p = grid.face_position(axis, i, j, k);
          grid.velocity(axis)[static_cast<std::size_t>(d.index(i, j, k))] =
              axis == 0 ? -0.02 * (p.y() - centre) / centre : 0.02 * (p.x() - centre) / centre;
        }
  }
  return grid;
}

void BM_BloodParticles(benchmark::State& state) {
  const FlowGrid grid = swirl(40);
  ConcentrationField field(grid);
  BloodParticleSettings settings;
  settings.lifetime = 2.0;
  settings.capacity = 12000;
  BloodParticles blood(settings, 1);
  const core::Vec3 site(0.012, 0.02, 0.02), normal(1, 0, 0);
  const double dt = 1e-3, rate = 1e-6;  // m³/s
  for (int step = 0; step < 2500; ++step) {
    blood.emit(site, normal, 0.05, rate * dt, grid, field);
    blood.advance(grid, nullptr, field, dt);
  }
  for (auto _ : state) {
    blood.emit(site, normal, 0.05, rate * dt, grid, field);
    blood.advance(grid, nullptr, field, dt);
  }
  state.counters["particles"] = static_cast<double>(blood.size());
}

}  // namespace

BENCHMARK(BM_BloodParticles)->Unit(benchmark::kMicrosecond);
