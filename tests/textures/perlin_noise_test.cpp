#include "textures/perlin_noise.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/random.h"
#include "textures/tissue_shading.h"

namespace viscera::textures {
namespace {

TEST(PerlinNoise, equals_the_reference_implementation_at_a_known_point) {
  // Value printed by Perlin's reference ImprovedNoise.java for (3.14, 42, 7).
  EXPECT_DOUBLE_EQ(PerlinNoise().noise(3.14, 42.0, 7.0), 0.13691995878400012);
}

TEST(PerlinNoise, vanishes_on_lattice_points) {
  const PerlinNoise noise;
  for (int i = -3; i < 4; ++i)
    EXPECT_EQ(noise.noise(i, 2 * i, -i), 0.0);
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

namespace viscera::textures {
namespace {

/// Perlin's ImprovedNoise.java transcribed literally (its own permutation table, fade, lerp and
/// grad), independent of the production code, to compare many points rather than one.
class ReferenceImprovedNoise {
 public:
  ReferenceImprovedNoise() {
    static const int permutation[] = {
        151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,
        103, 30,  69,  142, 8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,
        0,   26,  197, 62,  94,  252, 219, 203, 117, 35,  11,  32,  57,  177, 33,  88,  237, 149,
        56,  87,  174, 20,  125, 136, 171, 168, 68,  175, 74,  165, 71,  134, 139, 48,  27,  166,
        77,  146, 158, 231, 83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,  55,  46,
        245, 40,  244, 102, 143, 54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187,
        208, 89,  18,  169, 200, 196, 135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186,
        3,   64,  52,  217, 226, 250, 124, 123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212,
        207, 206, 59,  227, 47,  16,  58,  17,  182, 189, 28,  42,  223, 183, 170, 213, 119, 248,
        152, 2,   44,  154, 163, 70,  221, 153, 101, 155, 167, 43,  172, 9,   129, 22,  39,  253,
        19,  98,  108, 110, 79,  113, 224, 232, 178, 185, 112, 104, 218, 246, 97,  228, 251, 34,
        242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,  51,  145, 235, 249, 14,  239, 107,
        49,  192, 214, 31,  181, 199, 106, 157, 184, 84,  204, 176, 115, 121, 50,  45,  127, 4,
        150, 254, 138, 236, 205, 93,  222, 114, 67,  29,  24,  72,  243, 141, 128, 195, 78,  66,
        215, 61,  156, 180};
    for (int i = 0; i < 256; ++i)
      p_[256 + i] = p_[i] = permutation[i];
  }
  double noise(double x, double y, double z) const {
    const int X = static_cast<int>(std::floor(x)) & 255, Y = static_cast<int>(std::floor(y)) & 255,
              Z = static_cast<int>(std::floor(z)) & 255;
    x -= std::floor(x);
    y -= std::floor(y);
    z -= std::floor(z);
    const double u = fade(x), v = fade(y), w = fade(z);
    const int A = p_[X] + Y, AA = p_[A] + Z, AB = p_[A + 1] + Z, B = p_[X + 1] + Y, BA = p_[B] + Z,
              BB = p_[B + 1] + Z;
    return lerp(
        w,
        lerp(v, lerp(u, grad(p_[AA], x, y, z), grad(p_[BA], x - 1, y, z)),
             lerp(u, grad(p_[AB], x, y - 1, z), grad(p_[BB], x - 1, y - 1, z))),
        lerp(v, lerp(u, grad(p_[AA + 1], x, y, z - 1), grad(p_[BA + 1], x - 1, y, z - 1)),
             lerp(u, grad(p_[AB + 1], x, y - 1, z - 1), grad(p_[BB + 1], x - 1, y - 1, z - 1))));
  }

 private:
  static double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }
  static double lerp(double t, double a, double b) { return a + t * (b - a); }
  static double grad(int hash, double x, double y, double z) {
    const int h = hash & 15;
    const double u = h < 8 ? x : y, v = h < 4 ? y : h == 12 || h == 14 ? x : z;
    return ((h & 1) == 0 ? u : -u) + ((h & 2) == 0 ? v : -v);
  }
  int p_[512];
};

TEST(PerlinNoise, equals_the_transcribed_reference_at_many_points) {
  const ReferenceImprovedNoise reference;
  const PerlinNoise noise;
  core::Rng rng(11);
  for (int i = 0; i < 100000; ++i) {
    const double x = rng.uniform(-300, 300), y = rng.uniform(-300, 300), z = rng.uniform(-300, 300);
    ASSERT_EQ(noise.noise(x, y, z), reference.noise(x, y, z)) << x << " " << y << " " << z;
  }
}

TEST(PerlinNoise, two_dimensional_noise_is_the_plane_z_zero) {
  const PerlinNoise noise;
  core::Rng rng(12);
  for (int i = 0; i < 10000; ++i) {
    const double x = rng.uniform(-50, 50), y = rng.uniform(-50, 50);
    ASSERT_EQ(noise.noise(x, y), noise.noise(x, y, 0.0));
  }
}

TEST(PerlinNoise, rows_equal_point_evaluation_bit_for_bit) {
  for (const std::uint64_t seed : {0ULL, 5ULL}) {
    const PerlinNoise noise = seed == 0 ? PerlinNoise() : PerlinNoise(seed);
    std::vector<double> xs(1500);
    for (std::size_t i = 0; i < xs.size(); ++i)
      xs[i] = -7.3 + 0.0137 * static_cast<double>(i);
    // A few unsorted entries: the row code must handle any order.
    std::swap(xs[10], xs[900]);
    std::vector<double> out(xs.size());
    for (const double y : {-3.25, 0.0, 17.8}) {
      const double z = 2.0 * y + 0.3;
      noise.noise_row(xs.data(), static_cast<int>(xs.size()), y, z, out.data());
      for (std::size_t i = 0; i < xs.size(); ++i)
        ASSERT_EQ(out[i], noise.noise(xs[i], y, z));
      noise.noise_row(xs.data(), static_cast<int>(xs.size()), y, out.data());
      for (std::size_t i = 0; i < xs.size(); ++i)
        ASSERT_EQ(out[i], noise.noise(xs[i], y));
      noise.turbulence_row(xs.data(), static_cast<int>(xs.size()), y, 4, 0.5, out.data());
      for (std::size_t i = 0; i < xs.size(); ++i)
        ASSERT_EQ(out[i], noise.turbulence(xs[i], y, 4));
      noise.turbulence_row(xs.data(), static_cast<int>(xs.size()), y, z, 5, 0.6, out.data());
      for (std::size_t i = 0; i < xs.size(); ++i) {
        ASSERT_EQ(out[i], noise.turbulence(xs[i], y, z, 5, 0.6));
      }
      noise.fractal_row(xs.data(), static_cast<int>(xs.size()), y, 3, 0.5, out.data());
      for (std::size_t i = 0; i < xs.size(); ++i)
        ASSERT_EQ(out[i], noise.fractal_sum(xs[i], y, 3));
    }
  }
}

TEST(PerlinNoise, turbulence_stays_in_its_range_for_every_octave_count) {
  const PerlinNoise noise(21);
  core::Rng rng(22);
  for (int octaves = 1; octaves <= 8; ++octaves) {
    double bound = 0.0, amplitude = 1.0, sum = 0.0, maximum = 0.0;
    for (int o = 0; o < octaves; ++o, amplitude *= 0.5)
      bound += amplitude;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
      const double t = noise.turbulence(rng.uniform(-100, 100), rng.uniform(-100, 100),
                                        rng.uniform(-100, 100), octaves);
      ASSERT_GE(t, 0.0);
      ASSERT_LT(t, bound);
      sum += t;
      maximum = std::max(maximum, t);
    }
    // Not degenerate: the field uses a good part of its range.
    EXPECT_GT(sum / n, 0.1 * bound) << octaves;
    EXPECT_GT(maximum, 0.5 * bound) << octaves;
  }
}

TEST(PerlinNoise, mean_normalised_turbulence_matches_the_shading_constant) {
  // tissue_shading.h centres grain on kTurbulenceMean; keep that constant honest in the plane
  // (flat textures) and in space (solid textures).
  const PerlinNoise noise(3);
  core::Rng rng(4);
  double plane = 0.0, space = 0.0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double x = rng.uniform(0, 200), y = rng.uniform(0, 200), z = rng.uniform(0, 200);
    plane += noise.turbulence(x, y, 4) / 1.875;
    space += noise.turbulence(x, y, z, 4) / 1.875;
  }
  EXPECT_NEAR(plane / n, static_cast<double>(kTurbulenceMean), 0.015);
  EXPECT_NEAR(space / n, static_cast<double>(kTurbulenceMean), 0.015);
}

}  // namespace
}  // namespace viscera::textures
