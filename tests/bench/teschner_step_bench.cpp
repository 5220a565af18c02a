// One physics step of a Teschner body (seed 000 §3): forces from distance, area and volume
// terms plus a Verlet update, on a structured block of about 20k nodes — the size of issue 7's
// target (Teschner 2004 reported 114.61 ms for such a body on a 2.8 GHz Pentium 4) — and, side
// by side in the same process, Bullet's btSoftBody stepping the same tet mesh.

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <benchmark/benchmark.h>

#include <memory>

#include "core/random.h"
#include "simulator/physics/deformable_body.h"
#include "tests/support/tet_block.h"

namespace {

// 16³ cubes: 4,913 nodes. 26³ cubes: 19,683 nodes, 129k distance and 105k volume terms.
constexpr int kSmall = 16, kLarge = 26, kPlate = 99;

/// A block of n × n × n cubes, or with a second argument a plate of n × n × 1 cubes.
viscera::core::TetMesh benchmark_body(const benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  return state.range(1) == 1 ? viscera::testing::tet_block(n, n, 1, 0.002) : viscera::testing::tet_block(n, n, n, 0.002);
}

void BM_TeschnerStep(benchmark::State& state) {
  viscera::core::Material material;
  material.area_stiffness = 1.0;
  viscera::sim::DeformableBody body("block", benchmark_body(state), material);
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
// Blocks of 16³ and 26³ cubes, and a 99 × 99 × 1 plate: 20,000 nodes with about the issue's
// reference term counts (≈ 90k distance, 50k volume).
BENCHMARK(BM_TeschnerStep)->Args({kSmall, 0})->Args({kLarge, 0})->Args({kPlate, 1})->Unit(benchmark::kMillisecond);

/// Bullet's soft body on the same mesh: one node per tet-mesh node, a link per tet edge, a
/// tetra per tet, default solver settings (one position iteration), one 1 ms step per iteration.
void BM_BulletSoftBodyStep(benchmark::State& state) {
  const viscera::core::TetMesh mesh = benchmark_body(state);
  const viscera::sim::DeformableBody reference("block", mesh, viscera::core::Material{});

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
    masses.push_back(reference.masses()[i]);
  }
  auto* body = new btSoftBody(&world.getWorldInfo(), static_cast<int>(positions.size()), positions.data(), masses.data());
  for (const auto& [a, b] : reference.distance_terms().edges) body->appendLink(a, b);
  for (const auto& t : mesh.tets) body->appendTetra(t[0], t[1], t[2], t[3]);
  world.addSoftBody(body);
  for (auto _ : state) world.stepSimulation(1e-3, 0, 1e-3);
  state.counters["nodes"] = static_cast<double>(body->m_nodes.size());
  state.counters["links"] = static_cast<double>(body->m_links.size());
  state.counters["tetras"] = static_cast<double>(body->m_tetras.size());
  world.removeSoftBody(body);
  delete body;
}
BENCHMARK(BM_BulletSoftBodyStep)->Args({kSmall, 0})->Args({kLarge, 0})->Args({kPlate, 1})->Unit(benchmark::kMillisecond);

}  // namespace
