// The distension fluid's drag on free tissue (simulator/dynamics/fluid_drag.h) and on the chips
// of a resection (simulator/session/chip_drift.h): f = c (u − v), its load minus the gradient of
// its energy and its damping in the implicit matrix, so a free knot in a uniform flow takes the
// flow's velocity exactly as backward Euler's recurrence says; a chip's drag is a sphere's of its
// volume, shared by mass.

#include "simulator/dynamics/fluid_drag.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/error.h"
#include "simulator/dynamics/backward_euler.h"
#include "simulator/session/chip_drift.h"

namespace viscera::sim {
namespace {

SimulationState knots(const std::vector<double>& mass) {
  SimulationState state;
  std::vector<Vec3> rest;
  for (std::size_t i = 0; i < mass.size(); ++i)
    rest.push_back(Vec3(0.001 * static_cast<double>(i), 0.0005 * static_cast<double>(i % 2), 0));
  state.add_body("chip", rest, mass, {});
  return state;
}

TEST(FluidDrag, pulls_each_knot_towards_the_fluids_velocity_and_damps_it) {
  SimulationState state = knots({1e-3, 2e-3});
  FluidDrag drag;
  const Vec3 u(0.02, 0, -0.01);
  drag.set({{0, 3e-4, u}, {1, 1e-4, Vec3::Zero()}}, state);
  const std::vector<Vec3> v = {Vec3(0.01, 0.01, 0), Vec3(0, 0, 0.05)};
  std::vector<Vec3> f(2, Vec3::Zero());
  EXPECT_EQ(drag.add_forces(state.positions, v, f), 0.0);  // no work where it was set
  EXPECT_NEAR((f[0] - 3e-4 * (u - v[0])).norm(), 0.0, 1e-18);
  EXPECT_NEAR((f[1] - 1e-4 * (Vec3::Zero() - v[1])).norm(), 0.0, 1e-18);
  // The load is minus the energy's gradient (central differences).
  const double step = 1e-6;
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<Vec3> plus = state.positions, minus = state.positions;
    plus[0][axis] += step;
    minus[0][axis] -= step;
    const double gradient = (drag.energy(plus) - drag.energy(minus)) / (2.0 * step);
    EXPECT_NEAR(-gradient, 3e-4 * u[axis], 1e-12);
  }
  // Damping: ∂f/∂v = −c I on each knot's diagonal block.
  BlockPattern pattern(2);
  pattern.add(0, 1);
  BlockSparseMatrix damping;
  damping.set_pattern(pattern);
  damping.set_zero();
  drag.add_damping(state.positions, 2.0, damping);
  EXPECT_NEAR((damping.block(damping.diagonal_slot(0)) - 6e-4 * Mat3::Identity()).norm(), 0.0,
              1e-18);
  EXPECT_NEAR((damping.block(damping.diagonal_slot(1)) - 2e-4 * Mat3::Identity()).norm(), 0.0,
              1e-18);
  // A cut renumbers the knots: the drag goes until the session sets it again.
  drag.topology_changed(state, 0);
  EXPECT_TRUE(drag.drag().empty());
}

TEST(FluidDrag, a_free_knot_takes_the_flows_velocity_as_backward_euler_says) {
  // m dv/dt = c (u − v): backward Euler gives v_{n+1} = (m v_n + h c u) / (m + h c), so
  // v_n = u (1 − r^n) with r = m / (m + h c), and the knot's path is their sum times h.
  // A gram-sized knot: its drag (0.1 mN) stays above the Newton solver's absolute residual
  // tolerance (NewtonSettings, 1 µN) all the way.
  const double m = 2e-3, c = 4e-3, h = 1e-3;
  SimulationState state = knots({m});
  const Vec3 u(0.03, -0.01, 0.02);
  FluidDrag drag;
  drag.set({{0, c, u}}, state);
  BackwardEuler integrator;
  ForceTerm* terms[] = {&drag};
  integrator.topology_changed(state, terms);
  const Vec3 start = state.positions[0];
  const double r = m / (m + h * c);
  double travelled = 0.0;
  for (int n = 1; n <= 500; ++n) {
    integrator.step(state, terms, {h * (n - 1), h, n});
    travelled += h * (1.0 - std::pow(r, n));
  }
  const Vec3 expected_v = u * (1.0 - std::pow(r, 500));
  EXPECT_LT((state.velocities[0] - expected_v).norm(), 1e-9 * u.norm());
  EXPECT_LT((state.positions[0] - (start + travelled * u)).norm(), 1e-9 * travelled * u.norm());
  EXPECT_GT(expected_v.norm(), 0.6 * u.norm());  // half a second of drag: most of the way there
}

TEST(FluidDrag, refuses_a_knot_outside_the_state_and_a_bad_coefficient) {
  SimulationState state = knots({1e-3});
  FluidDrag drag;
  EXPECT_THROW(drag.set({{1, 1e-4, Vec3::Zero()}}, state), core::UsageError);
  EXPECT_THROW(drag.set({{0, -1e-4, Vec3::Zero()}}, state), core::UsageError);
  EXPECT_THROW(drag.set({{0, std::nan(""), Vec3::Zero()}}, state), core::UsageError);
  EXPECT_TRUE(drag.drag().empty());
}

TEST(ChipDrift, a_chip_gets_a_spheres_drag_shared_by_mass_from_the_flow_around_it) {
  // A chip of four knots in a uniform 2 cm/s flow along x.
  SimulationState state = knots({1e-6, 2e-6, 3e-6, 4e-6});
  fluid::FlowGrid grid(12, 12, 12, 1e-3, Vec3(-0.006, -0.006, -0.006));
  for (double& face : grid.velocity(0))
    face = 0.02;
  const double volume = 8e-9;  // m³: d = 2.48 mm
  const std::vector<Chip> chips = {{0, {0, 1, 2, 3}, volume}};
  const ChipDragSettings settings;
  const double d = 2.0 * std::cbrt(3.0 * volume / (4.0 * std::numbers::pi));
  const double mu = settings.fluid_density * settings.kinematic_viscosity;
  const auto total = [](const std::vector<NodeDrag>& drag) {
    double sum = 0.0;
    for (const NodeDrag& n : drag)
      sum += n.coefficient;
    return sum;
  };
  // At rest: Re = 0.02 d / ν ≈ 50, Schiller–Naumann's correction.
  std::vector<NodeDrag> drag = chip_drag(chips, state, grid, settings);
  ASSERT_EQ(drag.size(), 4u);
  const double reynolds = 0.02 * d / settings.kinematic_viscosity;
  EXPECT_NEAR(total(drag),
              3.0 * std::numbers::pi * mu * d * (1.0 + 0.15 * std::pow(reynolds, 0.687)), 1e-15);
  for (const NodeDrag& n : drag) {
    EXPECT_NEAR((n.fluid_velocity - Vec3(0.02, 0, 0)).norm(), 0.0, 1e-12);
    EXPECT_NEAR(n.coefficient / total(drag), 1e-6 * (n.node + 1) / 1e-5, 1e-12);  // by mass
  }
  // Moving with the flow: Re = 0, Stokes' drag.
  state.velocities.assign(4, Vec3(0.02, 0, 0));
  drag = chip_drag(chips, state, grid, settings);
  EXPECT_NEAR(total(drag), 3.0 * std::numbers::pi * mu * d, 1e-15);
}

}  // namespace
}  // namespace viscera::sim
