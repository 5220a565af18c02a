// One hybrid cut (seed 000 §5.1) through a gmsh ball: topology, relaxation, rest data, masses
// and the visual surface, as the core receives it (issue 17 target: ≥ 2,000 tets in ≤ 5 ms).
//   build/bin/viscera_cutting_bench --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include "core/mesh/surface_embedding.h"
#include "core/meshing/tet_mesher.h"
#include "core/primitives/icosphere.h"
#include "simulator/cutting/hybrid_cut.h"

namespace {

using namespace viscera;

struct Ball {
  core::TetMesh body;
  core::SurfaceMesh visual;
  core::SurfaceEmbedding embedding;
};

/// A gmsh ball of `radius` m from an icosphere of `level` subdivisions, with a visual surface
/// one level finer just inside it, embedded in its tets.
Ball make_ball(double radius, int level) {
  Ball out;
  out.body = core::mesh_closed_surface(core::make_icosphere(radius, level));
  out.body.node_mass = core::lumped_node_masses(out.body, 1000.0);
  out.visual = core::make_icosphere(radius * (1.0 - 1.0 / 300.0), level + 1);
  out.embedding = core::embed_points(out.visual.vertices, out.body);
  return out;
}

const Ball& ball() {
  static const Ball b = make_ball(0.03, 4);
  return b;
}

void report(benchmark::State& state, const sim::cutting::TopologyChange& change) {
  state.counters["tets"] = static_cast<double>(change.statistics.tets_before);
  state.counters["traversed"] = static_cast<double>(change.statistics.tets_traversed);
  state.counters["decomposed"] = static_cast<double>(change.statistics.tets_decomposed);
  state.counters["created"] =
      static_cast<double>(change.statistics.tets_after - change.statistics.tets_before);
  state.counters["relaxed"] = static_cast<double>(change.statistics.nodes_relaxed);
  state.counters["min_dihedral_after"] = change.statistics.min_dihedral_after_degrees;
}

void HybridCutPlanarThroughBall(benchmark::State& state) {
  const Ball& b = ball();
  const auto plane =
      sim::cutting::planar_cut_surface(core::Vec3(0.001, 0.002, 0.0005), core::Vec3(0.2, 1.0, 0.1),
                                       core::Vec3::UnitX(), 0.06, 0.06, 8);
  sim::cutting::TopologyChange change;
  for (auto _ : state) {
    change = state.range(0)
                 ? sim::cutting::hybrid_cut(b.body, b.body.nodes, plane, b.visual, b.embedding)
                 : sim::cutting::hybrid_cut(b.body, b.body.nodes, plane);
    benchmark::DoNotOptimize(change.mesh.tets.data());
  }
  report(state, change);
}
BENCHMARK(HybridCutPlanarThroughBall)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void HybridCutLoopSweepThroughBall(benchmark::State& state) {
  const Ball& b = ball();
  sim::cutting::LoopElectrode loop;
  loop.radius = 0.03;
  loop.segments = 24;
  std::vector<sim::cutting::LoopPose> sweep;
  for (int k = 0; k <= 16; ++k) {
    sim::cutting::LoopPose pose;
    pose.position =
        core::Vec3(0.0, 0.032 + 0.004 * std::sin(M_PI * k / 16.0), -0.065 + 0.13 * k / 16.0);
    sweep.push_back(pose);
  }
  const auto surface = sim::cutting::swept_loop_surface(loop, sweep);
  sim::cutting::TopologyChange change;
  for (auto _ : state) {
    change = sim::cutting::hybrid_cut(b.body, b.body.nodes, surface, b.visual, b.embedding);
    benchmark::DoNotOptimize(change.mesh.tets.data());
  }
  report(state, change);
}
BENCHMARK(HybridCutLoopSweepThroughBall)->Unit(benchmark::kMillisecond);

}  // namespace

namespace {

// A polyp-sized cut: a 6 mm ball of a few hundred tets with a finer visual surface, cut by a
// plane through its middle — the scale of a session's loop cut (issue 17: a session's cut
// ≤ 2 ms, of which this is the mesh part; the world's rebuild is BM_WorldRebuildAfterCut).
void HybridCutPlanarThroughSmallBall(benchmark::State& state) {
  static const Ball small = make_ball(0.006, 2);
  const auto plane = sim::cutting::planar_cut_surface(core::Vec3(0.0002, 0.0004, 0.0001),
                                                      core::Vec3(0.2, 1.0, 0.1),
                                                      core::Vec3::UnitX(), 0.015, 0.015, 8);
  sim::cutting::TopologyChange change;
  for (auto _ : state) {
    change = sim::cutting::hybrid_cut(small.body, small.body.nodes, plane, small.visual,
                                      small.embedding);
    benchmark::DoNotOptimize(change.mesh.tets.data());
  }
  report(state, change);
}
BENCHMARK(HybridCutPlanarThroughSmallBall)->Unit(benchmark::kMillisecond);

}  // namespace
