#pragma once
/// Perlin's improved gradient noise (Perlin 2002, "Improving Noise"), seed 001 §3.3 and
/// seed 000 §1.2: the base of procedural tissue textures.

#include <array>
#include <cstdint>

namespace viscera::textures {

/// 3D and 2D improved noise with a 256-entry permutation. Values lie in about [-1, 1] and equal
/// those of Perlin's reference implementation when built with the reference permutation.
///
/// Perlin publishes no separate 2D reference; the 2D functions are the 3D noise in the plane
/// z = 0 (the usual convention) and equal noise(x, y, 0.0) bit for bit.
///
/// The row functions evaluate many points with the same y and z at once, for textures: samples
/// that share a lattice cell share its hashes and gradients, and the per-sample work is a
/// branch-free loop that the compiler vectorises (AVX2 where the CPU has it, chosen at run time).
/// They return exactly what the point functions return for the same arguments.
class PerlinNoise {
 public:
  /// The reference permutation of Perlin 2002.
  PerlinNoise();
  /// A permutation shuffled from `seed` with the project's RNG (Fisher-Yates), for a
  /// different but equally distributed noise field per seed.
  explicit PerlinNoise(std::uint64_t seed);

  /// Noise at point (x, y, z); lattice spacing 1 in the point's units.
  double noise(double x, double y, double z) const;
  /// Noise at (x, y) = noise(x, y, 0).
  double noise(double x, double y) const;

  /// Sum of `octaves` octaves with frequency ×2 and amplitude × `persistence` per octave.
  double fractal_sum(double x, double y, double z, int octaves, double persistence = 0.5) const;
  double fractal_sum(double x, double y, int octaves, double persistence = 0.5) const;
  /// Perlin's turbulence: the same sum of |noise|, in [0, 1/(1-persistence)).
  double turbulence(double x, double y, double z, int octaves, double persistence = 0.5) const;
  double turbulence(double x, double y, int octaves, double persistence = 0.5) const;

  /// out[i] = noise(xs[i], y, z) for i < count. Fastest when xs ascends.
  void noise_row(const double* xs, int count, double y, double z, double* out) const;
  /// out[i] = noise(xs[i], y).
  void noise_row(const double* xs, int count, double y, double* out) const;
  /// out[i] = fractal_sum(xs[i], y, octaves, persistence) (2D).
  void fractal_row(const double* xs, int count, double y, int octaves, double persistence,
                   double* out) const;
  /// out[i] = turbulence(xs[i], y, octaves, persistence) (2D).
  void turbulence_row(const double* xs, int count, double y, int octaves, double persistence,
                      double* out) const;
  /// out[i] = turbulence(xs[i], y, z, octaves, persistence) (3D).
  void turbulence_row(const double* xs, int count, double y, double z, int octaves,
                      double persistence, double* out) const;

 private:
  template <bool kPlanar>
  void row(const double* xs, int count, double y, double z, double* out) const;
  template <bool kPlanar, bool kAbsolute>
  void octave_row(const double* xs, int count, double y, double z, int octaves, double persistence,
                  double* out) const;

  std::array<std::uint8_t, 512> p_{};  ///< permutation repeated twice, so p_[i + 1] needs no wrap
};

}  // namespace viscera::textures
