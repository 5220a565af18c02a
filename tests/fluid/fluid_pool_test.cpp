// The pool of seed 001 §4.3 (simulator/fluid/fluid_pool.h): its height is V / A over the lowest
// point, the suction takes water and blood in proportion at its rate and only within reach, and
// everything that came in is in the pool or was suctioned.

#include "simulator/fluid/fluid_pool.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"

using namespace viscera;
using namespace viscera::sim::fluid;

namespace {
const core::Vec3 kFloor(0.01, 0.02, -0.05);
const core::Vec3 kDown(0.0, 0.0, -9.81);  // gravity, any length
}  // namespace

TEST(FluidPool, height_follows_the_volume_over_the_area) {
  FluidPool pool(kFloor, kDown, 0.005);
  EXPECT_EQ(pool.height(), 0.0);
  pool.add_water(60e-6);
  pool.add_blood(40e-6);
  EXPECT_NEAR(pool.height(), 100e-6 / 0.005, 1e-15);  // 100 ml over 50 cm²: 2 cm
  EXPECT_NEAR(pool.blood_fraction(), 0.4, 1e-15);
  // Depth along gravity, measured from the surface 2 cm over the floor.
  EXPECT_NEAR(pool.depth(kFloor), 0.02, 1e-15);
  EXPECT_NEAR(pool.depth(kFloor + core::Vec3(0.3, -0.1, 0.05)), -0.03, 1e-15);
  EXPECT_NEAR((pool.surface_point(core::Vec3(0, 0, 0)) - core::Vec3(0, 0, -0.03)).norm(), 0.0,
              1e-15);
}

TEST(FluidPool, suction_takes_water_and_blood_in_proportion_at_its_rate) {
  FluidPool pool(kFloor, kDown, 0.005);
  pool.add_water(30e-6);
  pool.add_blood(10e-6);         // 40 ml, a quarter blood, 8 mm deep
  const SuctionOptions suction;  // 15 ml/s within 5 mm
  PoolVolumes drawn;
  for (int step = 0; step < 1000; ++step) {  // 1 s in 1 ms steps, the tip 4 mm over the surface
    const core::Vec3 tip = pool.surface_point(kFloor) + core::Vec3(0, 0, 0.004);
    const PoolVolumes d = pool.suck(tip, suction, 1e-3);
    drawn.water += d.water;
    drawn.blood += d.blood;
  }
  EXPECT_NEAR(drawn.total(), 15e-6, 1e-15);
  EXPECT_NEAR(drawn.blood / drawn.total(), 0.25, 1e-12);
  EXPECT_NEAR(pool.blood_fraction(), 0.25, 1e-12);
  EXPECT_NEAR(pool.contents().total(), 25e-6, 1e-15);
  EXPECT_NEAR(pool.suctioned().water + pool.contents().water, 30e-6, 1e-16);
  EXPECT_NEAR(pool.suctioned().blood + pool.contents().blood, 10e-6, 1e-16);
  // Out of reach (6 mm above the surface) nothing comes; under the surface it does.
  const core::Vec3 surface = pool.surface_point(kFloor);
  EXPECT_EQ(pool.suck(surface + core::Vec3(0, 0, 0.006), suction, 1e-3).total(), 0.0);
  EXPECT_GT(pool.suck(surface - core::Vec3(0, 0, 0.002), suction, 1e-3).total(), 0.0);
  // Drawing more than the pool holds empties it exactly.
  const PoolVolumes rest = pool.remove(1.0);
  EXPECT_EQ(pool.contents().total(), 0.0);
  EXPECT_GT(rest.total(), 0.0);
  EXPECT_EQ(pool.blood_fraction(), 0.0);
  EXPECT_EQ(pool.suck(kFloor, suction, 1e-3).total(), 0.0);
}

TEST(FluidPool, refuses_a_missing_gravity_a_bad_area_and_negative_volumes) {
  EXPECT_THROW(FluidPool(kFloor, core::Vec3::Zero(), 0.005), core::InputError);
  EXPECT_THROW(FluidPool(kFloor, kDown, 0.0), core::InputError);
  EXPECT_THROW(FluidPool(kFloor, kDown, -1.0), core::InputError);
  FluidPool pool(kFloor, kDown);
  EXPECT_EQ(pool.area(), FluidPool::kPelvicPoolArea);
  EXPECT_THROW(pool.add_water(-1e-6), core::InputError);
  EXPECT_THROW(pool.add_blood(std::nan("")), core::InputError);
  EXPECT_THROW(pool.remove(-1e-6), core::InputError);
  EXPECT_EQ(pool.contents().total(), 0.0);
}
