// The impact forces of irrigation drops (simulator/dynamics/impact_forces.h): constant forces on
// knots for one step, minus the gradient of their energy, summed per knot, cleared by a
// topology change, and refused for a knot outside the state.

#include "simulator/dynamics/impact_forces.h"

#include <gtest/gtest.h>

#include <vector>

#include "core/error.h"

namespace viscera::sim {
namespace {

SimulationState three_knots() {
  SimulationState state;
  const std::vector<Vec3> rest = {Vec3(0, 0, 0), Vec3(0.01, 0, 0), Vec3(0, 0.01, 0)};
  const std::vector<double> mass = {1e-3, 1e-3, 1e-3};
  state.add_body("sheet", rest, mass, {});
  return state;
}

TEST(ImpactForces, add_their_forces_per_knot_and_are_minus_the_gradient_of_their_energy) {
  SimulationState state = three_knots();
  ImpactForces term;
  term.set({{1, Vec3(0, 0, -2e-3)}, {2, Vec3(1e-3, 0, 0)}, {1, Vec3(0, 0, -1e-3)}}, state);
  EXPECT_NEAR((term.total() - Vec3(1e-3, 0, -3e-3)).norm(), 0.0, 1e-18);
  std::vector<Vec3> f(3, Vec3::Zero());
  const std::vector<Vec3> v(3, Vec3::Zero());
  EXPECT_EQ(term.add_forces(state.positions, v, f), 0.0);  // no work where they started
  EXPECT_EQ(f[0], Vec3::Zero());
  EXPECT_NEAR((f[1] - Vec3(0, 0, -3e-3)).norm(), 0.0, 1e-18);
  EXPECT_EQ(f[2], Vec3(1e-3, 0, 0));
  // Moving knot 1 by 1 mm along its force releases F · d of energy.
  std::vector<Vec3> x = state.positions;
  x[1] += Vec3(0, 0, -1e-3);
  EXPECT_NEAR(term.energy(x), -3e-6, 1e-18);
  // A cut renumbers the knots: the forces go (they last one step).
  term.topology_changed(state, 0);
  EXPECT_TRUE(term.forces().empty());
  std::vector<Vec3> g(3, Vec3::Zero());
  term.add_forces(state.positions, v, g);
  EXPECT_EQ(g[1], Vec3::Zero());
}

TEST(ImpactForces, refuse_a_knot_outside_the_state) {
  SimulationState state = three_knots();
  ImpactForces term;
  EXPECT_THROW(term.set({{3, Vec3::UnitZ()}}, state), core::UsageError);
  EXPECT_THROW(term.set({{-1, Vec3::UnitZ()}}, state), core::UsageError);
  EXPECT_TRUE(term.forces().empty());
}

}  // namespace
}  // namespace viscera::sim
