// The viscous step of the distension flow (simulator/fluid/viscous_diffusion.h): below the
// explicit limit one forward-Euler sweep stands in for the implicit solve, and the two agree to
// second order in νΔt/h²; both only take kinetic energy out of a box whose walls are at rest.

#include "simulator/fluid/viscous_diffusion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "simulator/fluid/flow_grid.h"
#include "tests/support/walled_flow_box.h"

using namespace viscera;
using namespace viscera::sim::fluid;

namespace {

/// A 10³ box of 1 mm cells walled all round, with a smooth swirl on its active faces, m/s.
FlowGrid swirling_box() {
  FlowGrid grid = test::walled_flow_box(10, 10, 10, 0.001);
  for (int axis = 0; axis < 3; ++axis) {
    const FaceDims d = grid.face_dims(axis);
    for (int k = 0; k < d.z; ++k)
      for (int j = 0; j < d.y; ++j)
        for (int i = 0; i < d.x; ++i) {
          const auto f = static_cast<std::size_t>(d.index(i, j, k));
          if (grid.face_states(axis)[f] != FaceState::Active) continue;
          const double x = 0.3 * i + axis, y = 0.4 * j, z = 0.5 * k;
          grid.velocity(axis)[f] = 0.05 * std::sin(x + y) * std::cos(z - x);
        }
  }
  return grid;
}

double kinetic_energy(const FlowGrid& grid) {
  double sum = 0.0;
  for (int axis = 0; axis < 3; ++axis)
    for (const double u : grid.velocity(axis))
      sum += 0.5 * u * u;
  return sum;
}

/// Largest difference between two grids' face velocities, m/s.
double largest_difference(const FlowGrid& a, const FlowGrid& b) {
  double m = 0.0;
  for (int axis = 0; axis < 3; ++axis)
    for (std::size_t f = 0; f < a.velocity(axis).size(); ++f)
      m = std::max(m, std::abs(a.velocity(axis)[f] - b.velocity(axis)[f]));
  return m;
}

/// The explicit and the implicit step of one Δt from the same swirl; returns the largest
/// difference between them, m/s.
double explicit_against_implicit(double time_step) {
  FlowGrid explicit_grid = swirling_box(), implicit_grid = swirling_box();
  DiffusionSettings settings;
  settings.viscosity = 1e-6;
  settings.time_step = time_step;
  settings.relative_tolerance = 1e-13;
  EXPECT_EQ(diffuse(explicit_grid, settings), 0);  // explicit: no solve
  settings.explicit_limit = 0.0;
  EXPECT_GT(diffuse(implicit_grid, settings), 0);
  return largest_difference(explicit_grid, implicit_grid);
}

}  // namespace

TEST(ViscousDiffusion, explicit_and_implicit_steps_agree_to_second_order_in_the_diffusion_number) {
  // νΔt/h² = 0.01 and 0.02: the difference is (νΔt/h²)²·L²u, so it grows fourfold.
  const double small = explicit_against_implicit(0.01);
  const double twice = explicit_against_implicit(0.02);
  EXPECT_GT(small, 0.0);
  EXPECT_NEAR(twice / small, 4.0, 0.6);
  // And it is a small part of what viscosity changes in one step.
  FlowGrid before = swirling_box(), after = swirling_box();
  DiffusionSettings settings;
  settings.viscosity = 1e-6;
  settings.time_step = 0.01;
  diffuse(after, settings);
  EXPECT_LT(small, 0.2 * largest_difference(before, after));
}

TEST(ViscousDiffusion, both_steps_take_energy_out_of_a_box_at_rest) {
  for (const double limit : {0.05, 0.0}) {
    FlowGrid grid = swirling_box();
    const double start = kinetic_energy(grid);
    DiffusionSettings settings;
    settings.viscosity = 1e-6;
    settings.time_step = 0.01;
    settings.explicit_limit = limit;
    ViscousDiffusion diffusion;
    double last = start;
    for (int step = 0; step < 20; ++step) {
      diffusion.diffuse(grid, settings);
      const double now = kinetic_energy(grid);
      EXPECT_LT(now, last) << "limit " << limit << ", step " << step;
      last = now;
    }
    EXPECT_LT(last, 0.9 * start);
  }
}
