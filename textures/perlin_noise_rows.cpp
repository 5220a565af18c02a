// Row evaluation of improved noise. Along a row y and z are fixed, so for every lattice cell the
// eight corner hashes, the gradients and the y/z parts of the corner dot products are computed
// once; each sample then needs only its x offset. Every one of Perlin's 16 gradients has exactly
// two non-zero components of ±1, so gx·x + (gy·y + gz·z) adds the same two non-zero terms as the
// reference grad(): the results are bit-identical (up to the sign of an exact zero).

#include <cmath>
#include <vector>

#include "textures/perlin_noise.h"

// An AVX2 clone of the cell loops where the CPU has it. Not under ThreadSanitizer: the dynamic
// loader runs a clone's resolver before the TSan runtime is initialised, and GCC instruments the
// resolver, so every program linking this file crashed at start-up in the TSan build.
#if defined(__SANITIZE_THREAD__)
#define VISCERA_AVX2_CLONES
#else
#define VISCERA_AVX2_CLONES [[gnu::target_clones("avx2", "default")]]
#endif

namespace viscera::textures {
namespace {

/// Gradient components of hash & 15, in the order of the reference grad().
constexpr double kGx[16] = {1, -1, 1, -1, 1, -1, 1, -1, 0, 0, 0, 0, 1, 0, -1, 0};
constexpr double kGy[16] = {1, 1, -1, -1, 0, 0, 0, 0, 1, -1, 1, -1, 1, -1, 1, -1};
constexpr double kGz[16] = {0, 0, 0, 0, 1, 1, -1, -1, 1, 1, -1, -1, 0, 1, 0, -1};

inline double fade(double t) {
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}
inline double lerp(double t, double a, double b) {
  return a + t * (b - a);
}

/// Samples of one lattice cell, 3D. gx[k], c[k]: x gradient and the y/z part of corner k's dot
/// product, corners in the reference order AA, BA, AB, BB, AA+1, BA+1, AB+1, BB+1.
VISCERA_AVX2_CLONES void cell_run_3d(const double* __restrict xs, int n, double x_floor,
                                     const double* __restrict gx, const double* __restrict c,
                                     double v, double w, double* __restrict out) {
  for (int i = 0; i < n; ++i) {
    const double x0 = xs[i] - x_floor;
    const double x1 = x0 - 1.0;
    const double u = fade(x0);
    out[i] = lerp(w,
                  lerp(v, lerp(u, gx[0] * x0 + c[0], gx[1] * x1 + c[1]),
                       lerp(u, gx[2] * x0 + c[2], gx[3] * x1 + c[3])),
                  lerp(v, lerp(u, gx[4] * x0 + c[4], gx[5] * x1 + c[5]),
                       lerp(u, gx[6] * x0 + c[6], gx[7] * x1 + c[7])));
  }
}

/// Samples of one lattice cell in the plane z = 0: lerp(0, a, b) is exactly a, so only the four
/// corners of the z = 0 face count.
VISCERA_AVX2_CLONES void cell_run_2d(const double* __restrict xs, int n, double x_floor,
                                     const double* __restrict gx, const double* __restrict c,
                                     double v, double* __restrict out) {
  for (int i = 0; i < n; ++i) {
    const double x0 = xs[i] - x_floor;
    const double x1 = x0 - 1.0;
    const double u = fade(x0);
    out[i] = lerp(v, lerp(u, gx[0] * x0 + c[0], gx[1] * x1 + c[1]),
                  lerp(u, gx[2] * x0 + c[2], gx[3] * x1 + c[3]));
  }
}

}  // namespace

template <bool kPlanar>
void PerlinNoise::row(const double* xs, int count, double y, double z, double* out) const {
  const double fy = std::floor(y), fz = std::floor(z);
  const int Y = static_cast<int>(fy) & 255, Z = static_cast<int>(fz) & 255;
  const double y0 = y - fy, z0 = z - fz;
  const double y1 = y0 - 1.0, z1 = z0 - 1.0;
  const double v = fade(y0), w = fade(z0);
  const double ys[8] = {y0, y0, y1, y1, y0, y0, y1, y1};
  const double zs[8] = {z0, z0, z0, z0, z1, z1, z1, z1};
  double gx[8], c[8];
  int i = 0;
  while (i < count) {
    const double x_floor = std::floor(xs[i]);
    const double x_next = x_floor + 1.0;
    int end = i + 1;
    while (end < count && xs[end] >= x_floor && xs[end] < x_next)
      ++end;
    const int X = static_cast<int>(x_floor) & 255;
    const int A = p_[X] + Y, AA = p_[A] + Z, AB = p_[A + 1] + Z;
    const int B = p_[X + 1] + Y, BA = p_[B] + Z, BB = p_[B + 1] + Z;
    int hashes[8] = {p_[AA], p_[BA], p_[AB], p_[BB], 0, 0, 0, 0};
    if constexpr (!kPlanar) {
      hashes[4] = p_[AA + 1];
      hashes[5] = p_[BA + 1];
      hashes[6] = p_[AB + 1];
      hashes[7] = p_[BB + 1];
    }
    for (int k = 0; k < (kPlanar ? 4 : 8); ++k) {
      const int h = hashes[k] & 15;
      gx[k] = kGx[h];
      c[k] = kGy[h] * ys[k] + kGz[h] * zs[k];
    }
    if constexpr (kPlanar) {
      cell_run_2d(xs + i, end - i, x_floor, gx, c, v, out + i);
    } else {
      cell_run_3d(xs + i, end - i, x_floor, gx, c, v, w, out + i);
    }
    i = end;
  }
}

template <bool kPlanar, bool kAbsolute>
void PerlinNoise::octave_row(const double* xs, int count, double y, double z, int octaves,
                             double persistence, double* out) const {
  std::vector<double> scaled(static_cast<std::size_t>(count)), values(scaled.size());
  for (int i = 0; i < count; ++i)
    out[i] = 0.0;
  double amplitude = 1.0, frequency = 1.0;
  for (int o = 0; o < octaves; ++o) {
    for (int i = 0; i < count; ++i)
      scaled[i] = xs[i] * frequency;
    row<kPlanar>(scaled.data(), count, y * frequency, kPlanar ? 0.0 : z * frequency, values.data());
    for (int i = 0; i < count; ++i) {
      out[i] += amplitude * (kAbsolute ? std::abs(values[i]) : values[i]);
    }
    amplitude *= persistence;
    frequency *= 2.0;
  }
}

void PerlinNoise::noise_row(const double* xs, int count, double y, double z, double* out) const {
  row<false>(xs, count, y, z, out);
}

void PerlinNoise::noise_row(const double* xs, int count, double y, double* out) const {
  row<true>(xs, count, y, 0.0, out);
}

void PerlinNoise::fractal_row(const double* xs, int count, double y, int octaves,
                              double persistence, double* out) const {
  octave_row<true, false>(xs, count, y, 0.0, octaves, persistence, out);
}

void PerlinNoise::turbulence_row(const double* xs, int count, double y, int octaves,
                                 double persistence, double* out) const {
  octave_row<true, true>(xs, count, y, 0.0, octaves, persistence, out);
}

void PerlinNoise::turbulence_row(const double* xs, int count, double y, double z, int octaves,
                                 double persistence, double* out) const {
  octave_row<false, true>(xs, count, y, z, octaves, persistence, out);
}

}  // namespace viscera::textures
