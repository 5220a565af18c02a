// Air bubbles in the distension fluid (simulator/fluid/air_bubbles.h): Stokes' rise speed with its
// cap; a bubble in still water rises at that speed and then clings under the wall; a pause before
// the inflow brings a burst, a steady inflow one bubble per stated volume; the flow flushes every
// bubble out through the outflow, none lost; the same seed gives the same bubbles.

#include "simulator/fluid/air_bubbles.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "tests/support/walled_flow_box.h"

using namespace viscera;
using namespace viscera::sim::fluid;

namespace {

/// `nx`×6×`nz` cells of 1 mm, walled all round.
FlowGrid closed_box(int nx, int nz) {
  return test::walled_flow_box(nx, 6, nz, 0.001);
}

core::Vec3 centre_of(const FlowGrid& grid, int i, int j, int k) {
  return grid.origin() + grid.cell_size() * core::Vec3(i + 0.5, j + 0.5, k + 0.5);
}

}  // namespace

TEST(AirBubbles, small_bubbles_rise_at_stokes_speed_and_large_ones_at_the_cap) {
  AirBubbleSettings settings;
  AirBubbles bubbles(settings, 1);
  // 2 Δρ g r² / (9 µ) for r = 0.1 mm in saline: 2·998·9.81·1e-8 / 9e-3.
  EXPECT_NEAR(bubbles.rise_speed(0.1e-3), 2.0 * 998.0 * 9.81 * 1e-8 / 9e-3, 1e-12);
  EXPECT_NEAR(bubbles.rise_speed(0.2e-3), 4.0 * bubbles.rise_speed(0.1e-3), 1e-12);
  EXPECT_DOUBLE_EQ(bubbles.rise_speed(1e-3), settings.max_rise_speed);
}

TEST(AirBubbles, a_bubble_in_still_water_rises_at_its_speed_then_clings_under_the_wall) {
  FlowGrid grid = closed_box(6, 40);
  AirBubbleSettings settings;
  settings.burst_count = 1;
  settings.min_radius = settings.max_radius = 0.1e-3;  // 21.8 mm/s
  AirBubbles bubbles(settings, 7);
  bubbles.admit(1e-6, 0.01, centre_of(grid, 3, 3, 3), grid);
  ASSERT_EQ(bubbles.size(), 1u);
  const core::Vec3 start = bubbles.positions()[0];
  const double speed = bubbles.rise_speed(0.1e-3);
  for (int step = 0; step < 25; ++step)
    bubbles.advance(grid, core::Vec3::UnitZ(), 0.02);
  const core::Vec3 moved = bubbles.positions()[0] - start;
  EXPECT_NEAR(moved.z(), speed * 0.5, 1e-9);
  EXPECT_NEAR(moved.head<2>().norm(), 0.0, 1e-12);
  EXPECT_FALSE(bubbles.clinging(0));
  // 1.5 s more: it reaches the top wall (38 mm up at most) and stays under it.
  for (int step = 0; step < 100; ++step)
    bubbles.advance(grid, core::Vec3::UnitZ(), 0.02);
  ASSERT_EQ(bubbles.size(), 1u);
  EXPECT_TRUE(bubbles.clinging(0));
  EXPECT_EQ(grid.cell_of(bubbles.positions()[0]).k, 38);
  EXPECT_EQ(bubbles.lost(), 0);
}

TEST(AirBubbles, a_start_after_a_pause_brings_a_burst_and_steady_inflow_one_per_volume) {
  FlowGrid grid = closed_box(8, 8);
  AirBubbleSettings settings;
  AirBubbles bubbles(settings, 3);
  const core::Vec3 inlet = centre_of(grid, 2, 3, 3);
  // 3 ml/s for 4 s in 1 ms steps: 12 ml, so the burst plus two bubbles (one per 5 ml).
  for (int step = 0; step < 4000; ++step)
    bubbles.admit(3e-6, 0.001, inlet, grid);
  EXPECT_EQ(bubbles.admitted(), settings.burst_count + 2);
  // A short stop (0.5 s) brings no new burst; a long one (2 s) does.
  for (int step = 0; step < 500; ++step)
    bubbles.admit(0.0, 0.001, inlet, grid);
  bubbles.admit(3e-6, 0.001, inlet, grid);
  EXPECT_EQ(bubbles.admitted(), settings.burst_count + 2);
  for (int step = 0; step < 2000; ++step)
    bubbles.admit(0.0, 0.001, inlet, grid);
  bubbles.admit(3e-6, 0.001, inlet, grid);
  EXPECT_EQ(bubbles.admitted(), 2 * settings.burst_count + 2);
}

TEST(AirBubbles, the_flow_flushes_every_bubble_through_the_outflow) {
  FlowGrid grid = closed_box(16, 6);
  for (int k = 1; k < 5; ++k)
    for (int j = 1; j < 5; ++j)
      grid.set_cell(15, j, k, FlowCell::Open);
  grid.update_faces();
  const auto& states = grid.face_states(0);
  for (std::size_t f = 0; f < states.size(); ++f)
    if (states[f] == FaceState::Active) grid.velocity(0)[f] = 0.05;
  AirBubbleSettings settings;
  AirBubbles bubbles(settings, 11);
  bubbles.admit(1e-6, 0.01, centre_of(grid, 2, 2, 2), grid);
  ASSERT_EQ(bubbles.admitted(), settings.burst_count);
  for (int step = 0; step < 20 && bubbles.size() > 0; ++step)
    bubbles.advance(grid, core::Vec3::Zero(), 0.04);
  EXPECT_EQ(bubbles.size(), 0u);
  EXPECT_EQ(bubbles.flushed(), bubbles.admitted());
  EXPECT_EQ(bubbles.lost(), 0);
}

TEST(AirBubbles, the_same_seed_gives_the_same_bubbles_and_bad_settings_are_refused) {
  FlowGrid grid = closed_box(8, 8);
  AirBubbles a(AirBubbleSettings{}, 5), b(AirBubbleSettings{}, 5);
  for (AirBubbles* bubbles : {&a, &b}) {
    bubbles->admit(2e-6, 0.01, centre_of(grid, 3, 3, 3), grid);
    for (int step = 0; step < 10; ++step)
      bubbles->advance(grid, core::Vec3::UnitZ(), 0.04);
  }
  EXPECT_EQ(a.positions(), b.positions());
  EXPECT_EQ(a.radii(), b.radii());
  AirBubbleSettings bad;
  bad.min_radius = 0.0;
  EXPECT_THROW(AirBubbles(bad, 1), core::UsageError);
}
