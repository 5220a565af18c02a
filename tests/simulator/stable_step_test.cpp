#include "simulator/physics/stable_step.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "simulator/dynamics/explicit_verlet.h"
#include "simulator/world/world.h"
#include "tests/simulator/sim_fixtures.h"

namespace viscera::sim {
namespace {

using core::Vec3;

TEST(StableStep, two_masses_on_a_spring_have_the_analytic_eigenvalue) {
  // One spring k between free masses m1, m2: ω² = k (1/m1 + 1/m2) along the spring.
  RankOneSystem system(2);
  const int nodes[2] = {0, 1};
  const Vec3 unit = Vec3(1.0, 2.0, 2.0) / 3.0;
  const Vec3 gradient[2] = {-unit, unit};
  system.add_term(nodes, gradient, 300.0);
  const std::vector<double> inverse_mass = {1.0 / 0.002, 1.0 / 0.005};
  EXPECT_NEAR(largest_eigenvalue(system, inverse_mass), 300.0 * (500.0 + 200.0), 1e-6 * 2.1e5);
  // Fixing the heavier mass leaves k / m1.
  EXPECT_NEAR(largest_eigenvalue(system, std::vector<double>{500.0, 0.0}), 300.0 * 500.0, 1e-3);
  EXPECT_EQ(largest_eigenvalue(system, std::vector<double>{0.0, 0.0}), 0.0);
}

TEST(StableStep, power_iteration_matches_a_dense_eigensolve_of_the_body_forces) {
  // The stiffness of a jiggled, partly fixed block from central differences of the body's own
  // forces at rest, solved densely (K v = λ M v), against the power iteration over its terms.
  core::Material material;
  material.density = 1000.0;
  material.distance_stiffness = 20000.0;
  material.volume_stiffness = 30000.0;
  material.area_stiffness = 50.0;
  material.distance_damping = 0.0;
  core::TetMesh mesh = viscera::testing::tet_block(2, 2, 2, 0.01);
  viscera::testing::jiggle(mesh.nodes, 0.0015, 7);
  mesh.fixed.assign(mesh.nodes.size(), 0);
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
    mesh.fixed[n] = mesh.nodes[n].z() < 0.002 ? 1 : 0;
  viscera::testing::TeschnerBody body(mesh, material);
  SimulationState& state = body.state;
  const auto terms = body.terms();
  std::vector<int> free;
  for (std::size_t n = 0; n < state.node_count(); ++n)
    if (state.inverse_masses[n] > 0.0) free.push_back(static_cast<int>(n));
  const int dofs = 3 * static_cast<int>(free.size());
  Eigen::MatrixXd k(dofs, dofs), m = Eigen::MatrixXd::Zero(dofs, dofs);
  const double eps = 1e-8;
  const std::vector<Vec3> zero(state.node_count(), Vec3::Zero());
  for (int c = 0; c < dofs; ++c) {
    const int node = free[static_cast<std::size_t>(c / 3)];
    std::vector<Vec3> plus, minus;
    for (const double sign : {1.0, -1.0}) {
      std::vector<Vec3> x = state.rest_positions;
      x[static_cast<std::size_t>(node)][c % 3] += sign * eps;
      std::vector<Vec3> f(x.size(), Vec3::Zero());
      for (ForceTerm* t : terms)
        t->add_forces(x, zero, f);
      (sign > 0 ? plus : minus) = f;
    }
    for (int r = 0; r < dofs; ++r) {
      const auto row_node = static_cast<std::size_t>(free[static_cast<std::size_t>(r / 3)]);
      k(r, c) = -(plus[row_node][r % 3] - minus[row_node][r % 3]) / (2.0 * eps);
    }
    m(c, c) = state.masses[static_cast<std::size_t>(node)];
  }
  const Eigen::MatrixXd symmetric = 0.5 * (k + k.transpose());
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(symmetric, m);
  const double dense = solver.eigenvalues().maxCoeff();

  // The terms' projected Hessians at rest (exact there: every constraint is zero).
  BlockPattern pattern(state.node_count());
  for (ForceTerm* t : terms)
    t->declare_blocks(pattern);
  BlockSparseMatrix stiffness;
  stiffness.set_pattern(pattern);
  for (ForceTerm* t : terms)
    t->add_stiffness(state.rest_positions, 1.0, true, stiffness);
  const double power = largest_eigenvalue(stiffness, state.inverse_masses, 5000, 1e-9);
  EXPECT_NEAR(power, dense, 1e-3 * dense);
  // The default iteration count already lands within the explicit integrator's safety margin,
  // from below.
  const double quick = largest_eigenvalue(stiffness, state.inverse_masses);
  EXPECT_LE(quick, dense * (1.0 + 1e-6));
  EXPECT_GT(quick, 0.95 * dense);
}

/// One damped oscillator x'' = −ω² x − c x' under position Verlet with the backward-difference
/// velocity (the velocity form the explicit integrator runs): the largest |x| over `steps` of h.
double oscillator_amplitude(double omega_squared, double c, double h, int steps) {
  double x = 1e-3, v = 0.0, largest = 0.0;
  for (int s = 0; s < steps; ++s) {
    v += h * (-omega_squared * x - c * v);
    x += h * v;
    largest = std::max(largest, std::abs(x));
  }
  return largest;
}

TEST(StableStep, the_verlet_bound_separates_bounded_from_growing_oscillations) {
  for (const double c : {0.0, 300.0, 3000.0}) {
    const double omega_squared = 1.0e8;
    const double h = verlet_stable_step(omega_squared, c);
    // Near the limit Verlet's discrete orbit is stretched (by 1/√(1 − h²ω²/4) undamped), but
    // bounded; beyond it the amplitude grows geometrically.
    EXPECT_LT(oscillator_amplitude(omega_squared, c, 0.98 * h, 4000), 1e-2) << "c = " << c;
    EXPECT_GT(oscillator_amplitude(omega_squared, c, 1.03 * h, 4000), 1.0) << "c = " << c;
  }
  EXPECT_DOUBLE_EQ(verlet_stable_step(1.0e8, 0.0), 2.0e-4);   // 2/ω
  EXPECT_DOUBLE_EQ(verlet_stable_step(0.0, 1000.0), 2.0e-3);  // 2/c
  EXPECT_TRUE(std::isinf(verlet_stable_step(0.0, 0.0)));
}

TEST(StableStep, a_world_at_its_spectral_substeps_loses_energy_from_a_jiggled_start) {
  core::Scenario scenario;
  scenario.materials["soft"] = viscera::testing::soft_test_material(5.0);
  const core::SceneObject block = viscera::testing::held_block("block", 3, 3, 3, 0.005);
  scenario.objects.push_back(block);
  scenario.session.gravity = Vec3::Zero();
  scenario.session.time_step = 1e-3;
  World world(scenario, IntegratorKind::ExplicitVerlet);
  ASSERT_GT(world.substeps(), 1);
  // A random 0.3 mm jiggle excites the highest modes, the ones that would blow up first.
  auto x = world.bodies()[0].positions();
  std::vector<Vec3> moved(x.begin(), x.end());
  viscera::testing::jiggle(moved, 3e-4, 11);
  for (std::size_t n = 0; n < x.size(); ++n)
    if (world.bodies()[0].inverse_masses()[n] > 0.0) x[n] = moved[n];
  const double initial = world.energies().total();
  double previous = initial;
  ASSERT_GT(previous, 0.0);
  for (int interval = 0; interval < 10; ++interval) {
    for (int s = 0; s < 20; ++s)
      world.step();
    const double energy = world.energies().total();
    EXPECT_LE(energy, previous * (1.0 + 1e-9)) << "after " << 20 * (interval + 1) << " steps";
    previous = energy;
  }
  EXPECT_LT(previous, 0.5 * initial);  // damped, not merely bounded
}

}  // namespace
}  // namespace viscera::sim
