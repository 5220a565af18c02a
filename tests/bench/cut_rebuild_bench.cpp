// Issue 17's cut target, end to end: a cut through ≥ 2,000 tets — topology, relaxation, rest
// data, visual surface and solver rebuild — ≤ 5 ms. One planar hybrid cut (seed 000 §5.1)
// through a gmsh ball of soft tissue held at its base, with its embedded visual surface, then
// World::topology_changed as a session calls it (every term's caches, the contact hash, the
// proxy's surface and the implicit solver's block pattern). A new world is built, untimed,
// before each cut.
//   build/bin/viscera_bench --benchmark_filter=BM_CutThroughBallWithRebuild

#include <benchmark/benchmark.h>

#include "core/mesh/surface_embedding.h"
#include "core/meshing/tet_mesher.h"
#include "core/primitives/icosphere.h"
#include "simulator/cutting/hybrid_cut.h"
#include "simulator/session/cut_topology.h"
#include "simulator/world/world.h"
#include "tests/support/tet_block.h"

namespace {

using namespace viscera;

struct HeldBall {
  core::Scenario scenario;
  core::SurfaceMesh visual;
  core::SurfaceEmbedding embedding;
};

/// A 3 cm ball meshed with 3 mm tets inside a level-3 icosphere, held where z < −2.4 cm, and
/// a level-4 visual surface just inside it.
const HeldBall& held_ball() {
  static const HeldBall ball = [] {
    HeldBall b;
    constexpr double kRadius = 0.03;
    core::TetMeshingOptions options;
    options.cell_size = 0.003;
    core::SceneObject object;
    object.id = "ball";
    object.material = "soft";
    object.body_kind = core::BodyKind::TetMesh;
    object.body = core::mesh_closed_surface(core::make_icosphere(kRadius, 3), options);
    object.body.fixed.assign(object.body.nodes.size(), 0);
    for (std::size_t n = 0; n < object.body.nodes.size(); ++n)
      object.body.fixed[n] = object.body.nodes[n].z() < -0.8 * kRadius ? 1 : 0;
    b.visual = core::make_icosphere(kRadius * (1.0 - 1.0 / 300.0), 4);
    b.embedding = core::embed_points(b.visual.vertices, object.body);
    b.scenario.materials["soft"] = testing::soft_test_material();
    b.scenario.objects.push_back(std::move(object));
    return b;
  }();
  return ball;
}

void BM_CutThroughBallWithRebuild(benchmark::State& state) {
  const HeldBall& ball = held_ball();
  const auto plane =
      sim::cutting::planar_cut_surface(core::Vec3(0.001, 0.002, 0.0005), core::Vec3(0.2, 1.0, 0.1),
                                       core::Vec3::UnitX(), 0.06, 0.06, 8);
  sim::cutting::CutStatistics statistics;
  std::size_t nodes_after = 0;
  for (auto _ : state) {
    state.PauseTiming();
    auto world = std::make_unique<sim::World>(ball.scenario);
    state.ResumeTiming();
    const sim::BodyModel& model = *world->models()[0];
    const auto positions = world->state().range(world->state().positions, 0);
    const std::vector<core::Vec3> current(positions.begin(), positions.end());
    const auto change =
        sim::cutting::hybrid_cut(model.mesh, current, plane, ball.visual, ball.embedding);
    world->topology_changed(0, sim::topology_of_cut(change, world->held_nodes(0)));
    state.PauseTiming();
    statistics = change.statistics;
    nodes_after = world->state().node_count();
    world.reset();
    state.ResumeTiming();
  }
  state.counters["tets"] = static_cast<double>(statistics.tets_before);
  state.counters["traversed"] = static_cast<double>(statistics.tets_traversed);
  state.counters["created"] = static_cast<double>(statistics.tets_after - statistics.tets_before);
  state.counters["nodes_after"] = static_cast<double>(nodes_after);
}
BENCHMARK(BM_CutThroughBallWithRebuild)->Unit(benchmark::kMillisecond);

}  // namespace
