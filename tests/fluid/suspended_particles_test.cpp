// Particles suspended in the distension fluid (simulator/fluid/suspended_particles.h), as tissue
// debris: Stokes' settling speed for a tissue shred in saline, capped in magnitude; a shred in
// still saline sinks at that speed, then rests on the floor without entering it; an open cell
// below draws it out; a wall that closes over a shred moves it to an open neighbour.

#include "simulator/fluid/suspended_particles.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "tests/support/walled_flow_box.h"

using namespace viscera;
using namespace viscera::sim::fluid;

namespace {

/// Tissue in saline: 50 kg/m³ denser, so it settles.
SuspensionSettings tissue() {
  SuspensionSettings s;
  s.density_difference = -50.0;
  return s;
}

core::Vec3 centre_of(const FlowGrid& grid, int i, int j, int k) {
  return grid.origin() + grid.cell_size() * core::Vec3(i + 0.5, j + 0.5, k + 0.5);
}

}  // namespace

TEST(SuspendedParticles, a_tissue_shred_settles_at_stokes_speed_and_a_large_one_at_the_cap) {
  SuspendedParticles debris(tissue());
  // 2 Δρ g r² / (9 µ) for r = 0.3 mm: 2·(−50)·9.81·9e-8 / 9e-3 = −9.81 mm/s.
  EXPECT_NEAR(debris.drift_speed(0.3e-3), -2.0 * 50.0 * 9.81 * 9e-8 / 9e-3, 1e-12);
  EXPECT_NEAR(debris.drift_speed(0.6e-3), 4.0 * debris.drift_speed(0.3e-3), 1e-12);
  EXPECT_DOUBLE_EQ(debris.drift_speed(0.1), -tissue().max_drift_speed);
}

TEST(SuspendedParticles, a_shred_in_still_saline_sinks_then_rests_on_the_floor) {
  const FlowGrid grid = test::walled_flow_box(6, 6, 30, 0.001);
  SuspendedParticles debris(tissue());
  ASSERT_TRUE(debris.add(centre_of(grid, 3, 3, 20), 0.3e-3));
  const core::Vec3 start = debris.positions()[0];
  const double speed = debris.drift_speed(0.3e-3);  // negative: down
  for (int step = 0; step < 25; ++step)
    debris.advance(grid, core::Vec3::UnitZ(), 0.02);
  const core::Vec3 moved = debris.positions()[0] - start;
  EXPECT_NEAR(moved.z(), speed * 0.5, 1e-9);  // 4.9 mm down
  EXPECT_NEAR(moved.head<2>().norm(), 0.0, 1e-12);
  EXPECT_FALSE(debris.resting(0));
  // 3 s more (29 mm at most): it reaches the floor's layer and stays above it.
  for (int step = 0; step < 150; ++step)
    debris.advance(grid, core::Vec3::UnitZ(), 0.02);
  ASSERT_EQ(debris.size(), 1u);
  EXPECT_TRUE(debris.resting(0));
  EXPECT_EQ(grid.cell_of(debris.positions()[0]).k, 1);
  EXPECT_EQ(debris.lost(), 0);
  EXPECT_EQ(debris.flushed(), 0);
}

TEST(SuspendedParticles, an_outflow_below_draws_the_settling_shreds_out) {
  FlowGrid grid = test::walled_flow_box(8, 8, 12, 0.001);
  for (int j = 1; j < 7; ++j)
    for (int i = 1; i < 7; ++i)
      grid.set_cell(i, j, 1, FlowCell::Open);
  grid.update_faces();
  SuspendedParticles debris(tissue());
  for (int i = 2; i < 6; ++i)
    ASSERT_TRUE(debris.add(centre_of(grid, i, 4, 9), 0.4e-3));
  for (int step = 0; step < 60 && debris.size() > 0; ++step)
    debris.advance(grid, core::Vec3::UnitZ(), 0.04);
  EXPECT_EQ(debris.size(), 0u);
  EXPECT_EQ(debris.flushed(), 4);
  EXPECT_EQ(debris.lost(), 0);
}

TEST(SuspendedParticles, a_shred_a_wall_closes_over_moves_to_an_open_neighbour) {
  FlowGrid grid = test::walled_flow_box(8, 8, 8, 0.001);
  SuspendedParticles debris(tissue());
  ASSERT_TRUE(debris.add(centre_of(grid, 4, 4, 4), 0.2e-3));
  grid.set_cell(4, 4, 4, FlowCell::Solid);  // the wall moved over it
  grid.update_faces();
  debris.advance(grid, core::Vec3::Zero(), 0.01);
  ASSERT_EQ(debris.size(), 1u);
  EXPECT_NE(grid.cell_or_solid(grid.cell_of(debris.positions()[0])), FlowCell::Solid);
  EXPECT_LE((debris.positions()[0] - centre_of(grid, 4, 4, 4)).norm(), 1.0001e-3);
}

TEST(SuspendedParticles, capacity_bounds_the_admissions_and_bad_settings_are_refused) {
  SuspensionSettings settings = tissue();
  settings.capacity = 2;
  SuspendedParticles debris(settings);
  EXPECT_TRUE(debris.add(core::Vec3::Zero(), 1e-4));
  EXPECT_TRUE(debris.add(core::Vec3::Zero(), 1e-4));
  EXPECT_FALSE(debris.add(core::Vec3::Zero(), 1e-4));
  EXPECT_EQ(debris.admitted(), 2);
  settings.liquid_viscosity = 0.0;
  EXPECT_THROW(SuspendedParticles{settings}, core::UsageError);
}
