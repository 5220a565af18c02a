#include "textures/perlin_noise.h"

#include <cmath>
#include <numeric>

#include "core/random.h"

namespace viscera::textures {
namespace {

constexpr std::array<std::uint8_t, 256> kReferencePermutation = {
    151, 160, 137, 91,  90,  15,  131, 13,  201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103,
    30,  69,  142, 8,   99,  37,  240, 21,  10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,
    197, 62,  94,  252, 219, 203, 117, 35,  11,  32,  57,  177, 33,  88,  237, 149, 56,  87,  174,
    20,  125, 136, 171, 168, 68,  175, 74,  165, 71,  134, 139, 48,  27,  166, 77,  146, 158, 231,
    83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,  41,  55,  46,  245, 40,  244, 102, 143,
    54,  65,  25,  63,  161, 1,   216, 80,  73,  209, 76,  132, 187, 208, 89,  18,  169, 200, 196,
    135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,  52,  217, 226, 250, 124,
    123, 5,   202, 38,  147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,  58,  17,
    182, 189, 28,  42,  223, 183, 170, 213, 119, 248, 152, 2,   44,  154, 163, 70,  221, 153, 101,
    155, 167, 43,  172, 9,   129, 22,  39,  253, 19,  98,  108, 110, 79,  113, 224, 232, 178, 185,
    112, 104, 218, 246, 97,  228, 251, 34,  242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,
    51,  145, 235, 249, 14,  239, 107, 49,  192, 214, 31,  181, 199, 106, 157, 184, 84,  204, 176,
    115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,  222, 114, 67,  29,  24,  72,  243,
    141, 128, 195, 78,  66,  215, 61,  156, 180};

/// Quintic fade 6t⁵ − 15t⁴ + 10t³: continuous second derivative at lattice points.
inline double fade(double t) {
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}
inline double lerp(double t, double a, double b) {
  return a + t * (b - a);
}

/// Components of the 16 gradients of the reference grad(): hash & 15 → (gx, gy, gz).
constexpr double kGx[16] = {1, -1, 1, -1, 1, -1, 1, -1, 0, 0, 0, 0, 1, 0, -1, 0};
constexpr double kGy[16] = {1, 1, -1, -1, 0, 0, 0, 0, 1, -1, 1, -1, 1, -1, 1, -1};
constexpr double kGz[16] = {0, 0, 0, 0, 1, 1, -1, -1, 1, 1, -1, -1, 0, 1, 0, -1};

/// Dot product with one of the 12 edge-midpoint gradients (16 cases, 4 repeated). Perlin's
/// grad() picks ±u ± v with branches; every gradient has exactly two non-zero components of ±1,
/// so the table form adds the same two terms and gives the same value, without the branch
/// mispredictions that random hashes cause.
inline double grad(int hash, double x, double y, double z) {
  const int h = hash & 15;
  return kGx[h] * x + (kGy[h] * y + kGz[h] * z);
}

}  // namespace

PerlinNoise::PerlinNoise() {
  for (int i = 0; i < 512; ++i)
    p_[i] = kReferencePermutation[i & 255];
}

PerlinNoise::PerlinNoise(std::uint64_t seed) {
  std::array<std::uint8_t, 256> permutation{};
  std::iota(permutation.begin(), permutation.end(), std::uint8_t{0});
  core::Rng rng(seed);
  for (int i = 255; i > 0; --i)
    std::swap(permutation[i], permutation[rng.uniform_int(0, i)]);
  for (int i = 0; i < 512; ++i)
    p_[i] = permutation[i & 255];
}

double PerlinNoise::noise(double x, double y, double z) const {
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const int X = static_cast<int>(fx) & 255, Y = static_cast<int>(fy) & 255,
            Z = static_cast<int>(fz) & 255;
  x -= fx;
  y -= fy;
  z -= fz;
  const double u = fade(x), v = fade(y), w = fade(z);
  const int A = p_[X] + Y, AA = p_[A] + Z, AB = p_[A + 1] + Z;
  const int B = p_[X + 1] + Y, BA = p_[B] + Z, BB = p_[B + 1] + Z;
  return lerp(
      w,
      lerp(v, lerp(u, grad(p_[AA], x, y, z), grad(p_[BA], x - 1, y, z)),
           lerp(u, grad(p_[AB], x, y - 1, z), grad(p_[BB], x - 1, y - 1, z))),
      lerp(v, lerp(u, grad(p_[AA + 1], x, y, z - 1), grad(p_[BA + 1], x - 1, y, z - 1)),
           lerp(u, grad(p_[AB + 1], x, y - 1, z - 1), grad(p_[BB + 1], x - 1, y - 1, z - 1))));
}

double PerlinNoise::fractal_sum(double x, double y, double z, int octaves,
                                double persistence) const {
  double sum = 0.0, amplitude = 1.0, frequency = 1.0;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * noise(x * frequency, y * frequency, z * frequency);
    amplitude *= persistence;
    frequency *= 2.0;
  }
  return sum;
}

double PerlinNoise::turbulence(double x, double y, double z, int octaves,
                               double persistence) const {
  double sum = 0.0, amplitude = 1.0, frequency = 1.0;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * std::abs(noise(x * frequency, y * frequency, z * frequency));
    amplitude *= persistence;
    frequency *= 2.0;
  }
  return sum;
}

double PerlinNoise::noise(double x, double y) const {
  return noise(x, y, 0.0);
}

double PerlinNoise::fractal_sum(double x, double y, int octaves, double persistence) const {
  return fractal_sum(x, y, 0.0, octaves, persistence);
}

double PerlinNoise::turbulence(double x, double y, int octaves, double persistence) const {
  return turbulence(x, y, 0.0, octaves, persistence);
}

}  // namespace viscera::textures
