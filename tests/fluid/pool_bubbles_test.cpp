#include "simulator/fluid/pool_bubbles.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace viscera::sim::fluid {
namespace {

const core::Vec3 kFloor(0.0, 0.0, -0.05), kDown(0.0, 0.0, -1.0);
const core::Vec3 kFast(0.0, 0.0, -1.0), kSlow(0.0, 0.0, -0.2);  // m/s into the water

/// A pool 2 cm deep (100 ml over 50 cm²) with its waves.
struct Pool {
  FluidPool pool{kFloor, kDown};
  PoolWaves waves{kFloor, kDown, FluidPool::kPelvicPoolArea};
  Pool() { pool.add_water(100e-6); }
  core::Vec3 at(double x, double y) const { return kFloor + core::Vec3(x, y, pool.height()); }
};

TEST(PoolBubbles, fast_drops_trap_air_that_floats_in_the_surface) {
  Pool p;
  PoolBubbles bubbles;
  bubbles.drop_lands(p.at(0.0, 0.0), kSlow, p.pool);
  EXPECT_EQ(bubbles.trapped(), 0);  // too slow to trap air
  for (int k = 0; k < 10; ++k)
    bubbles.drop_lands(p.at(0.002 * k, 0.001 * k), kFast, p.pool);
  EXPECT_EQ(bubbles.trapped(), 10);
  p.waves.drop_lands(p.at(0.0, 0.0), kFast, 1e-6, p.pool.height());
  for (int step = 0; step < 100; ++step) {
    p.waves.step(1e-3, p.pool.height());
    bubbles.step(1e-3, p.pool, p.waves, false, core::Vec3::Zero(), 0.0);
  }
  ASSERT_EQ(bubbles.bubbles().size(), 10u);
  for (const PoolBubble& b : bubbles.bubbles()) {
    const double level = p.pool.height() + p.waves.elevation(b.position);
    EXPECT_NEAR(b.position.z() - kFloor.z(), level, 1e-12);
    EXPECT_GE(b.radius, bubbles.options().min_radius);
    EXPECT_LE(b.radius, bubbles.options().max_radius);
  }
}

TEST(PoolBubbles, overlapping_bubbles_part_and_near_ones_gather_until_they_touch) {
  Pool p;
  PoolBubbleOptions options;
  options.min_radius = options.max_radius = 0.5e-3;  // touching at 1 mm
  options.min_life = options.max_life = 100.0;
  for (const double start : {0.3e-3, 1.6e-3}) {
    PoolBubbles bubbles(options);
    bubbles.drop_lands(p.at(0.0, 0.0), kFast, p.pool);
    bubbles.drop_lands(p.at(start, 0.0), kFast, p.pool);
    for (int step = 0; step < 3000; ++step)
      bubbles.step(1e-3, p.pool, p.waves, false, core::Vec3::Zero(), 0.0);
    const double apart = (bubbles.bubbles()[1].position - bubbles.bubbles()[0].position).norm();
    EXPECT_NEAR(apart, 1e-3, 0.05e-3) << "from " << start;
  }
}

TEST(PoolBubbles, bubbles_burst_with_age_a_dry_pool_or_the_suction) {
  Pool p;
  PoolBubbles aged, dried, sucked;
  for (PoolBubbles* b : {&aged, &dried, &sucked})
    for (int k = 0; k < 20; ++k)
      b->drop_lands(p.at(0.003 * (k % 5), 0.003 * (k / 5)), kFast, p.pool);
  const double last = aged.options().max_life;
  for (int step = 0; step * 1e-3 < last + 0.01; ++step)
    aged.step(1e-3, p.pool, p.waves, false, core::Vec3::Zero(), 0.0);
  EXPECT_TRUE(aged.bubbles().empty());
  EXPECT_EQ(aged.burst(), 20);
  FluidPool empty(kFloor, kDown);
  dried.step(1e-3, empty, p.waves, false, core::Vec3::Zero(), 0.0);
  EXPECT_TRUE(dried.bubbles().empty());
  // The cannula over the corner bubble (0, 0) with a 5 mm reach takes those within it.
  sucked.step(1e-3, p.pool, p.waves, true, p.at(0.0, 0.0), 0.005);
  EXPECT_GT(sucked.burst(), 0);
  EXPECT_LT(sucked.burst(), 20);
  for (const PoolBubble& b : sucked.bubbles())
    EXPECT_GT((b.position - p.at(0.0, 0.0)).norm(), 0.005);
}

TEST(PoolBubbles, the_same_drops_give_the_same_bubbles) {
  Pool p;
  PoolBubbles a, b;
  for (PoolBubbles* bubbles : {&a, &b})
    for (int step = 0; step < 300; ++step) {
      bubbles->drop_lands(p.at(0.0005 * (step % 11), 0.0003 * (step % 7)), kFast, p.pool);
      bubbles->step(1e-3, p.pool, p.waves, false, core::Vec3::Zero(), 0.0);
    }
  ASSERT_EQ(a.bubbles().size(), b.bubbles().size());
  for (std::size_t k = 0; k < a.bubbles().size(); ++k)
    EXPECT_EQ(a.bubbles()[k].position, b.bubbles()[k].position);
  EXPECT_LE(static_cast<int>(a.bubbles().size()), a.options().capacity);
}

TEST(PoolBubbles, refuses_options_out_of_order) {
  PoolBubbleOptions o;
  o.max_radius = 0.1e-3;  // below the smallest
  EXPECT_THROW(PoolBubbles{o}, core::InputError);
  o = {};
  o.capacity = 0;
  EXPECT_THROW(PoolBubbles{o}, core::InputError);
}

}  // namespace
}  // namespace viscera::sim::fluid
