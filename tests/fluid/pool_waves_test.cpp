#include "simulator/fluid/pool_waves.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "core/random.h"

namespace viscera::sim::fluid {
namespace {

const core::Vec3 kFloor(0.01, -0.02, 0.03), kDown(0.0, 0.0, -1.0);
constexpr double kArea = 0.005;             // the pelvic pool, 50 cm²: a disc of radius 4 cm
constexpr double kDrop = 1e-8;              // m³, one jet drop
const core::Vec3 kFalling(0.0, 0.0, -0.8);  // m/s

TEST(PoolWaves, waves_move_water_but_never_make_or_lose_it) {
  PoolWaves waves(kFloor, kDown, kArea);
  core::Rng rng(3);
  double landed = 0.0;
  for (int step = 0; step < 2000; ++step) {
    if (step < 500) {
      const core::Vec3 at = kFloor + core::Vec3(rng.uniform(-0.05, 0.05), rng.uniform(-0.05, 0.05),
                                                0.02);  // some beyond the rim: land at the rim
      waves.drop_lands(at, kFalling, kDrop, 0.02);
      landed += kDrop;
    }
    waves.step(1e-3, 0.02);
  }
  EXPECT_LT(std::abs(waves.displaced_volume()), 1e-9 * landed);
  EXPECT_GT(waves.largest_elevation(), 0.0);
}

/// s until |η| at 2 cm from the centre first passes 5 % of its largest value over 0.3 s, after
/// one drop at the centre of a pool `depth` m deep.
double arrival_at_two_centimetres(double depth) {
  PoolWaves waves(kFloor, kDown, kArea, 64);
  waves.drop_lands(kFloor, kFalling, 1e-6, depth);
  std::vector<double> trace;
  for (int step = 0; step < 300; ++step) {
    waves.step(1e-3, depth);
    trace.push_back(std::abs(waves.elevation_at(0.02, 0.0)));
  }
  const double peak = *std::max_element(trace.begin(), trace.end());
  for (std::size_t k = 0; k < trace.size(); ++k)
    if (trace[k] > 0.05 * peak) return 1e-3 * static_cast<double>(k + 1);
  return 1.0;
}

TEST(PoolWaves, waves_run_at_the_shallow_water_speed) {
  // √(g H): 0.44 m/s in 2 cm of water, 0.89 m/s in 8 cm — twice as fast.
  const double shallow = arrival_at_two_centimetres(0.02);
  const double deep = arrival_at_two_centimetres(0.08);
  EXPECT_NEAR(shallow, 0.02 / std::sqrt(9.81 * 0.02), 0.4 * 0.02 / std::sqrt(9.81 * 0.02));
  EXPECT_NEAR(shallow / deep, 2.0, 0.4);
}

TEST(PoolWaves, a_slosh_dies_out_and_an_emptied_pool_is_flat) {
  PoolWaves waves(kFloor, kDown, kArea);
  waves.drop_lands(kFloor + core::Vec3(0.01, 0.0, 0.02), kFalling, 1e-6, 0.02);
  double early = 0.0;
  for (int step = 0; step < 3000; ++step) {
    waves.step(1e-3, 0.02);
    if (step < 200) early = std::max(early, waves.largest_elevation());
  }
  EXPECT_LT(waves.largest_elevation(), 0.01 * early);
  waves.drop_lands(kFloor, kFalling, 1e-6, 0.02);
  waves.step(1e-3, 0.0);  // suctioned dry
  EXPECT_EQ(waves.largest_elevation(), 0.0);
}

TEST(PoolWaves, the_same_landings_give_the_same_bits) {
  PoolWaves a(kFloor, kDown, kArea), b(kFloor, kDown, kArea);
  for (PoolWaves* w : {&a, &b})
    for (int step = 0; step < 200; ++step) {
      w->drop_lands(kFloor + core::Vec3(0.001 * (step % 7), 0.0, 0.0), kFalling, kDrop, 0.01);
      w->step(1e-3, 0.01);
    }
  EXPECT_EQ(a.heights(), b.heights());
}

TEST(PoolWaves, refuses_a_pool_without_area_gravity_or_cells) {
  EXPECT_THROW(PoolWaves(kFloor, kDown, 0.0), core::InputError);
  EXPECT_THROW(PoolWaves(kFloor, core::Vec3::Zero(), kArea), core::InputError);
  EXPECT_THROW(PoolWaves(kFloor, kDown, kArea, 2), core::InputError);
}

}  // namespace
}  // namespace viscera::sim::fluid
