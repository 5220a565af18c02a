// The distension flow solver (simulator/fluid, seed 000 §2.2): the projection leaves no more
// divergence than stated and is a projection; fluid at rest under gravity in a closed box stays
// at rest; what enters through an inflow leaves through the outflow; threads change no bit; bad
// settings are refused.

#include "simulator/fluid/stable_fluids.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "core/random.h"
#include "simulator/fluid/flow_grid.h"
#include "simulator/fluid/pressure_projection.h"

using namespace viscera;
using namespace viscera::sim::fluid;

namespace {

/// An 12×10×8 box of 2 mm cells walled all round, with a solid block inside; `open` adds an
/// outflow cell in the middle of one wall, `inflow` a wall cell blowing in at 0.1 m/s opposite.
FlowGrid box(bool open, bool inflow) {
  FlowGrid grid(12, 10, 8, 0.002);
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 10; ++j)
      for (int i = 0; i < 12; ++i) {
        const bool wall = i == 0 || j == 0 || k == 0 || i == 11 || j == 9 || k == 7;
        const bool block = i >= 5 && i <= 6 && j >= 3 && j <= 5 && k >= 2 && k <= 4;
        if (wall || block) grid.set_cell(i, j, k, FlowCell::Solid);
      }
  if (open) grid.set_cell(11, 5, 4, FlowCell::Open);
  if (inflow) grid.set_cell(0, 5, 4, FlowCell::Solid, core::Vec3(0.1, 0.0, 0.0));
  grid.update_faces();
  return grid;
}

void randomise(FlowGrid& grid, std::uint64_t seed) {
  core::Rng rng(seed);
  for (int axis = 0; axis < 3; ++axis) {
    const auto& states = grid.face_states(axis);
    for (std::size_t f = 0; f < states.size(); ++f)
      if (states[f] == FaceState::Active) grid.velocity(axis)[f] = rng.uniform(-0.05, 0.05);
  }
}

/// Net flow out of the box through the faces of cell (i,j,k), m³/s.
double outflow_of_cell(const FlowGrid& grid, int i, int j, int k) {
  const double area = grid.cell_size() * grid.cell_size();
  const FaceDims du = grid.face_dims(0), dv = grid.face_dims(1), dw = grid.face_dims(2);
  const auto u = [&](int a, int b, int c) { return grid.velocity(0)[du.index(a, b, c)]; };
  const auto v = [&](int a, int b, int c) { return grid.velocity(1)[dv.index(a, b, c)]; };
  const auto w = [&](int a, int b, int c) { return grid.velocity(2)[dw.index(a, b, c)]; };
  return area *
         (u(i + 1, j, k) - u(i, j, k) + v(i, j + 1, k) - v(i, j, k) + w(i, j, k + 1) - w(i, j, k));
}

}  // namespace

TEST(PressureProjection, leaves_no_more_divergence_than_stated_and_is_a_projection) {
  for (const bool open : {false, true}) {
    FlowGrid grid = box(open, false);
    randomise(grid, 7);
    ProjectionSettings settings;
    settings.threads = 1;
    settings.time_step = 0.01;
    settings.divergence_tolerance = 1e-6;
    const ProjectionResult first = project(grid, settings);
    EXPECT_TRUE(first.converged);
    EXPECT_LE(first.max_divergence, 1e-6);
    EXPECT_GT(first.iterations, 0);
    // A second projection of a divergence-free field changes it by no more than the tolerance.
    std::array<std::vector<double>, 3> projected{grid.velocity(0), grid.velocity(1),
                                                 grid.velocity(2)};
    project(grid, settings);
    for (int axis = 0; axis < 3; ++axis)
      for (std::size_t f = 0; f < projected[axis].size(); ++f)
        EXPECT_NEAR(grid.velocity(axis)[f], projected[axis][f], 1e-8);
  }
}

TEST(StableFluids, fluid_at_rest_under_gravity_in_a_closed_box_stays_at_rest) {
  FlowGrid grid = box(false, false);
  FlowSettings settings;
  settings.threads = 1;
  settings.acceleration = core::Vec3(0.0, 0.0, -9.81);
  settings.divergence_tolerance = 1e-9;
  for (int s = 0; s < 20; ++s) {
    const FlowStepReport report = step_flow(grid, settings);
    ASSERT_TRUE(report.converged);
  }
  double fastest = 0.0;
  for (int axis = 0; axis < 3; ++axis)
    for (const double value : grid.velocity(axis))
      fastest = std::max(fastest, std::abs(value));
  EXPECT_LT(fastest, 1e-6);  // against 0.2 m/s of free fall in 20 steps
  // The pressure is hydrostatic: it grows downwards by g per metre.
  const double top = grid.pressure()[grid.cell_index(2, 2, 6)];
  const double bottom = grid.pressure()[grid.cell_index(2, 2, 1)];
  EXPECT_NEAR(bottom - top, 9.81 * 5 * grid.cell_size(), 1e-6);
}

TEST(StableFluids, what_the_inflow_brings_leaves_through_the_outflow) {
  FlowGrid grid = box(true, true);
  FlowSettings settings;
  settings.threads = 1;
  settings.viscosity = 1e-6;
  settings.divergence_tolerance = 1e-8;
  for (int s = 0; s < 10; ++s)
    ASSERT_TRUE(step_flow(grid, settings).converged);
  const double area = grid.cell_size() * grid.cell_size();
  const double inflow = 0.1 * area;  // m³/s through the one inflow face
  // Flow into the open cell from the box equals the inflow (the box holds no more fluid).
  const double into_outflow =
      -outflow_of_cell(grid, 11, 5, 4) + area * grid.velocity(0)[grid.face_dims(0).index(12, 5, 4)];
  EXPECT_NEAR(into_outflow, inflow, 1e-6 * inflow);
  EXPECT_LE(grid.max_divergence(), 1e-8);
}

TEST(StableFluids, any_number_of_threads_gives_the_same_bits) {
  std::array<std::vector<double>, 3> reference;
  for (const int threads : {1, 2, 3}) {
    FlowGrid grid = box(true, true);
    randomise(grid, 11);
    FlowSettings settings;
    settings.viscosity = 1e-4;
    settings.threads = threads;
    for (int s = 0; s < 5; ++s)
      step_flow(grid, settings);
    for (int axis = 0; axis < 3; ++axis) {
      if (threads == 1) {
        reference[axis] = grid.velocity(axis);
      } else {
        EXPECT_EQ(grid.velocity(axis), reference[axis]) << threads << " threads, axis " << axis;
      }
    }
  }
}

TEST(StableFluids, bad_settings_are_refused) {
  FlowGrid grid = box(false, false);
  FlowSettings settings;
  settings.time_step = 0.0;
  EXPECT_THROW(step_flow(grid, settings), core::UsageError);
  settings.time_step = 0.01;
  settings.viscosity = -1.0;
  EXPECT_THROW(step_flow(grid, settings), core::UsageError);
  EXPECT_THROW(FlowGrid(0, 4, 4, 0.001), core::UsageError);
  EXPECT_THROW(FlowGrid(4, 4, 4, 0.0), core::UsageError);
}

TEST(FlowGrid, the_cell_of_a_point_is_the_floor_of_its_grid_coordinates_inside_or_out) {
  // 4×3×2 cells of 5 mm with the corner at (−10, 0, 20) mm.
  const FlowGrid grid(4, 3, 2, 0.005, core::Vec3(-0.010, 0.0, 0.020));
  const CellCoord inside = grid.cell_of(core::Vec3(-0.0001, 0.0126, 0.0251));
  EXPECT_EQ(inside.i, 1);
  EXPECT_EQ(inside.j, 2);
  EXPECT_EQ(inside.k, 1);
  EXPECT_TRUE(grid.contains(inside));
  EXPECT_EQ(grid.cell_index(inside), grid.cell_index(1, 2, 1));
  // Just below the corner is cell −1, not 0 (floor, not truncation), and outside: solid.
  const CellCoord below = grid.cell_of(core::Vec3(-0.0101, 0.0001, 0.0201));
  EXPECT_EQ(below.i, -1);
  EXPECT_FALSE(grid.contains(below));
  EXPECT_EQ(grid.cell_or_solid(below), FlowCell::Solid);
  EXPECT_FALSE(grid.contains(grid.cell_of(core::Vec3(0.0101, 0.0001, 0.0201))));
}
