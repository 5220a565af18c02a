#include "textures/perlin_noise.h"

#include <gtest/gtest.h>

#include <cmath>

namespace viscera::textures {
namespace {

TEST(PerlinNoise, equals_the_reference_implementation_at_a_known_point) {
  // Value printed by Perlin's reference ImprovedNoise.java for (3.14, 42, 7).
  EXPECT_DOUBLE_EQ(PerlinNoise().noise(3.14, 42.0, 7.0), 0.13691995878400012);
}

TEST(PerlinNoise, vanishes_on_lattice_points) {
  const PerlinNoise noise;
  for (int i = -3; i < 4; ++i) EXPECT_EQ(noise.noise(i, 2 * i, -i), 0.0);
}

TEST(PerlinNoise, stays_in_range_and_turbulence_is_non_negative) {
  const PerlinNoise noise(7);
  for (int i = 0; i < 20000; ++i) {
    const double x = 0.137 * i, y = 0.071 * i, z = 0.029 * i;
    const double n = noise.noise(x, y, z);
    ASSERT_LE(std::abs(n), 1.0);
    const double t = noise.turbulence(x, y, z, 4);
    ASSERT_GE(t, 0.0);
    ASSERT_LE(t, 2.0);
  }
}

TEST(PerlinNoise, seeds_change_the_field_reproducibly) {
  EXPECT_EQ(PerlinNoise(3).noise(0.3, 0.7, 1.1), PerlinNoise(3).noise(0.3, 0.7, 1.1));
  EXPECT_NE(PerlinNoise(3).noise(0.3, 0.7, 1.1), PerlinNoise(4).noise(0.3, 0.7, 1.1));
}

}  // namespace
}  // namespace viscera::textures
