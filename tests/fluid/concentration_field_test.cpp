// Blood carried by the flow (simulator/fluid/concentration_field.h): a closed cavity keeps every
// drop (issue 18: to 1e-6 per 1,000 steps), no cell goes negative or above the blood it started
// with, and with an inflow and an outflow what is in the cavity plus what left is what was shed.

#include "simulator/fluid/concentration_field.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/random.h"
#include "simulator/fluid/pressure_projection.h"
#include "simulator/fluid/stable_fluids.h"

using namespace viscera;
using namespace viscera::sim::fluid;

namespace {

/// A walled 16×14×12 box of 1 mm cells, a swirl projected divergence-free in it.
FlowGrid stirred_box(bool open) {
  FlowGrid grid(16, 14, 12, 0.001);
  for (int k = 0; k < 12; ++k)
    for (int j = 0; j < 14; ++j)
      for (int i = 0; i < 16; ++i)
        if (i == 0 || j == 0 || k == 0 || i == 15 || j == 13 || k == 11)
          grid.set_cell(i, j, k, FlowCell::Solid);
  if (open) {
    grid.set_cell(0, 7, 6, FlowCell::Solid, core::Vec3(0.05, 0.0, 0.0));
    grid.set_cell(15, 3, 6, FlowCell::Open);
  }
  grid.update_faces();
  core::Rng rng(5);
  for (int axis = 0; axis < 3; ++axis) {
    const auto& states = grid.face_states(axis);
    for (std::size_t f = 0; f < states.size(); ++f)
      if (states[f] == FaceState::Active) grid.velocity(axis)[f] = rng.uniform(-0.03, 0.03);
  }
  ProjectionSettings projection;
  projection.threads = 1;
  projection.divergence_tolerance = 1e-9;
  project(grid, projection);
  return grid;
}

}  // namespace

TEST(ConcentrationField, a_closed_cavity_keeps_its_blood_and_stays_within_bounds) {
  const FlowGrid grid = stirred_box(false);
  ConcentrationField blood(grid);
  const double shed = 2e-8;  // 0.02 ml
  ASSERT_EQ(blood.add_blood(grid, core::Vec3(0.005, 0.006, 0.004), shed), shed);
  EXPECT_EQ(blood.add_blood(grid, core::Vec3(0.0002, 0.006, 0.004), shed), 0.0);  // in a wall
  const double start = blood.total_volume(grid);
  EXPECT_NEAR(start, shed, 1e-20);
  const double peak = shed / 1e-9;  // fraction in the one cell
  int substeps = 0;
  for (int s = 0; s < 1000; ++s)
    substeps += blood.advect(grid, 0.05);
  EXPECT_GT(substeps, 1000);  // the swirl is faster than a cell per step somewhere
  EXPECT_NEAR(blood.total_volume(grid), start, 1e-6 * start);
  EXPECT_EQ(blood.drained_volume(), 0.0);
  double lowest = 1.0, highest = 0.0;
  int reached = 0;
  for (int k = 1; k < 11; ++k)
    for (int j = 1; j < 13; ++j)
      for (int i = 1; i < 15; ++i) {
        const double c = blood.at(grid, i, j, k);
        lowest = std::min(lowest, c);
        highest = std::max(highest, c);
        reached += c > 1e-6 * peak;
      }
  EXPECT_GE(lowest, 0.0);
  EXPECT_LE(highest, peak);
  EXPECT_GT(reached, 100);  // it spread through the cavity
}

TEST(ConcentrationField, blood_in_the_cavity_plus_blood_drained_is_blood_shed) {
  const FlowGrid grid = stirred_box(true);
  ConcentrationField blood(grid);
  double shed = 0.0;
  for (int s = 0; s < 500; ++s) {
    if (s < 100) shed += blood.add_blood(grid, core::Vec3(0.008, 0.007, 0.006), 1e-10);
    blood.advect(grid, 0.01);
  }
  EXPECT_GT(blood.drained_volume(), 0.1 * shed);
  EXPECT_NEAR(blood.total_volume(grid) + blood.drained_volume(), shed, 1e-9 * shed);
}

TEST(ConcentrationField,
     a_cell_spills_what_it_holds_above_its_volume_and_a_closing_wall_pushes_it_out) {
  // 5×5×5 cells of 1 mm, walled all round: 3 mm³ of blood in the centre cell (fraction 3).
  FlowGrid grid(5, 5, 5, 0.001);
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 5; ++i)
        if (i == 0 || j == 0 || k == 0 || i == 4 || j == 4 || k == 4)
          grid.set_cell(i, j, k, FlowCell::Solid);
  grid.update_faces();
  ConcentrationField field(grid);
  const core::Vec3 centre(0.0025, 0.0025, 0.0025);
  EXPECT_DOUBLE_EQ(field.add_blood(grid, centre, 3e-9), 3e-9);
  EXPECT_NEAR(field.spill(grid), 2e-9, 1e-21);
  EXPECT_DOUBLE_EQ(field.at(grid, 2, 2, 2), 1.0);
  EXPECT_NEAR(field.at(grid, 1, 2, 2), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(field.total_volume(grid), 3e-9, 1e-21);
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 5; ++i)
        EXPECT_LE(field.at(grid, i, j, k), 1.0);
  // The wall closes over the centre cell: its blood goes to the six cells around it.
  grid.set_cell(2, 2, 2, FlowCell::Solid);
  grid.update_faces();
  EXPECT_NEAR(field.settle(grid), 1e-9, 1e-21);
  EXPECT_EQ(field.at(grid, 2, 2, 2), 0.0);
  EXPECT_NEAR(field.at(grid, 2, 3, 2), 0.5, 1e-15);
  EXPECT_NEAR(field.total_volume(grid), 3e-9, 1e-21);
}
