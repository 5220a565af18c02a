// Steps of a Teschner body (seed 000 §3) under the core's integrators, on structured blocks of
// 2 mm cubes: one implicit (backward Euler) step of a ~20k-node body — issue 16's target of
// ≤ 10 ms — and, per SIMULATED SECOND, the same block under backward Euler, explicit Verlet
// (spectral sub-steps) and, side by side in the same process, Bullet's btSoftBody on the same
// tet mesh and masses, at settings where it holds the block's shape (its sag is reported).

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <memory>

#include "simulator/world/world.h"
#include "tests/support/tet_block.h"

namespace {

using viscera::core::Vec3;

// 16³ cubes: 4,913 nodes. 26³ cubes: 19,683 nodes, 129k distance and 105k volume terms.
constexpr int kSmall = 10, kMedium = 16, kLarge = 26;

/// A block of n³ cubes of 2 mm held at its base (z = 0), soft tissue (20 kPa), under gravity.
viscera::core::Scenario block_scenario(int n) {
  viscera::core::Scenario scenario;
  viscera::core::Material material = viscera::testing::soft_test_material(20.0);
  scenario.materials["soft"] = material;
  viscera::core::SceneObject block = viscera::testing::held_block("block", n, n, n, 0.002);
  scenario.objects.push_back(block);
  scenario.session.gravity = Vec3(0.0, 0.0, -9.81);
  return scenario;
}

void add_counters(benchmark::State& state, const viscera::sim::World& world) {
  state.counters["nodes"] = static_cast<double>(world.state().node_count());
  state.counters["newton"] = world.last_step_statistics().newton_iterations;
  state.counters["cg"] = world.last_step_statistics().linear_iterations;
  state.counters["substeps"] = world.substeps();
  state.counters["sag_mm"] = 1e3 * world.bodies()[0].max_displacement();
}

/// One implicit step while the block is settling under gravity (the loaded case).
void BM_ImplicitStep(benchmark::State& state) {
  viscera::sim::World world(block_scenario(static_cast<int>(state.range(0))),
                            viscera::sim::IntegratorKind::BackwardEuler);
  for (int s = 0; s < 5; ++s)
    world.step();
  for (auto _ : state)
    world.step();
  add_counters(state, world);
}
BENCHMARK(BM_ImplicitStep)->Arg(kMedium)->Arg(kLarge)->Unit(benchmark::kMillisecond);

/// One simulated second (1000 steps of 1 ms) from rest under gravity.
void BM_TeschnerSimulatedSecond(benchmark::State& state) {
  const auto kind = state.range(1) == 0 ? viscera::sim::IntegratorKind::BackwardEuler
                                        : viscera::sim::IntegratorKind::ExplicitVerlet;
  for (auto _ : state) {
    state.PauseTiming();
    auto world = std::make_unique<viscera::sim::World>(
        block_scenario(static_cast<int>(state.range(0))), kind);
    state.ResumeTiming();
    for (int s = 0; s < 1000; ++s)
      world->step();
    state.PauseTiming();
    add_counters(state, *world);
    world.reset();
    state.ResumeTiming();
  }
}
BENCHMARK(BM_TeschnerSimulatedSecond)
    ->Args({kSmall, 0})
    ->Args({kSmall, 1})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

/// Bullet's soft body on the same mesh and masses: a link per tet edge, a tetra per tet, the
/// base nodes fixed (mass 0), `iterations` position iterations; one simulated second of 1 ms
/// steps per iteration. sag_mm is its largest displacement at the end: Bullet holds the
/// block's shape only with enough iterations.
void BM_BulletSoftBodySimulatedSecond(benchmark::State& state) {
  const viscera::core::Scenario scenario = block_scenario(static_cast<int>(state.range(0)));
  const viscera::sim::World reference(scenario);
  const auto& mesh = scenario.objects[0].body;
  double sag = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    btSoftBodyRigidBodyCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher(&configuration);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btSoftRigidDynamicsWorld world(&dispatcher, &broadphase, &solver, &configuration);
    world.setGravity(btVector3(0, 0, -9.81));
    world.getWorldInfo().m_gravity = btVector3(0, 0, -9.81);
    std::vector<btVector3> positions;
    std::vector<btScalar> masses;
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
      positions.emplace_back(mesh.nodes[i].x(), mesh.nodes[i].y(), mesh.nodes[i].z());
      masses.push_back(mesh.fixed[i] ? 0.0 : reference.state().masses[i]);
    }
    auto* body = new btSoftBody(&world.getWorldInfo(), static_cast<int>(positions.size()),
                                positions.data(), masses.data());
    std::vector<std::array<int, 2>> edges;
    for (const auto& t : mesh.tets)
      for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b)
          edges.push_back({std::min(t[a], t[b]), std::max(t[a], t[b])});
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    for (const auto& [a, b] : edges)
      body->appendLink(a, b);
    for (const auto& t : mesh.tets)
      body->appendTetra(t[0], t[1], t[2], t[3]);
    body->m_cfg.piterations = static_cast<int>(state.range(1));
    world.addSoftBody(body);
    state.ResumeTiming();
    for (int s = 0; s < 1000; ++s)
      world.stepSimulation(1e-3, 0, 1e-3);
    state.PauseTiming();
    sag = 0.0;
    for (int i = 0; i < body->m_nodes.size(); ++i) {
      const btVector3& x = body->m_nodes[i].m_x;
      sag = std::max(sag,
                     (Vec3(x.x(), x.y(), x.z()) - mesh.nodes[static_cast<std::size_t>(i)]).norm());
    }
    state.counters["nodes"] = static_cast<double>(body->m_nodes.size());
    world.removeSoftBody(body);
    delete body;
    state.ResumeTiming();
  }
  state.counters["sag_mm"] = 1e3 * sag;
  state.counters["piterations"] = static_cast<double>(state.range(1));
}
BENCHMARK(BM_BulletSoftBodySimulatedSecond)
    ->Args({kSmall, 1})
    ->Args({kSmall, 10})
    ->Args({kSmall, 40})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace
