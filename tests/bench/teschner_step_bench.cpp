// One physics step of a Teschner body (seed 000 §3): forces from distance, area and volume
// terms plus a Verlet update, on a structured block of about 20k nodes — the size of the
// issue's target (Teschner 2004 reported 114.61 ms for such a body on a 2.8 GHz Pentium 4).

#include <benchmark/benchmark.h>

#include "core/random.h"
#include "simulator/physics/deformable_body.h"

namespace {

viscera::core::TetMesh block(int nx, int ny, int nz, double cell) {
  viscera::core::TetMesh mesh;
  const auto index = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) mesh.nodes.emplace_back(cell * i, cell * j, cell * k);
  static constexpr int kPaths[6][2] = {{1, 3}, {1, 5}, {2, 3}, {2, 6}, {4, 5}, {4, 6}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const auto corner = [&](int c) { return index(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1)); };
        for (const auto& path : kPaths) mesh.tets.push_back({corner(0), corner(path[0]), corner(path[1]), corner(7)});
      }
  viscera::core::orient_tets_positively(mesh);
  return mesh;
}

void BM_TeschnerStep(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  viscera::core::Material material;
  material.area_stiffness = 1.0;
  viscera::sim::DeformableBody body("block", block(n, n, n, 0.002), material);
  viscera::core::Rng rng(1);
  for (auto& p : body.positions()) p += viscera::core::Vec3(rng.uniform(-1e-4, 1e-4), 0.0, 0.0);
  const double h = body.stable_time_step();
  const viscera::core::Vec3 gravity(0, 0, -9.81);
  for (auto _ : state) {
    body.compute_forces(gravity, h);
    body.integrate(h);
  }
  state.counters["nodes"] = static_cast<double>(body.node_count());
  state.counters["distance_terms"] = static_cast<double>(body.distance_terms().edges.size());
  state.counters["volume_terms"] = static_cast<double>(body.volume_terms().tets.size());
  state.counters["area_terms"] = static_cast<double>(body.area_terms().triangles.size());
}
// 26³ = 17,576 nodes; 27³ = 19,683 nodes, ≈ 113k distance and 105k volume terms.
BENCHMARK(BM_TeschnerStep)->Arg(16)->Arg(26)->Unit(benchmark::kMillisecond);

}  // namespace
