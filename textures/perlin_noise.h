#pragma once
/// Perlin's improved gradient noise (Perlin 2002, "Improving Noise"), seed 001 §3.3 and
/// seed 000 §1.2: the base of procedural tissue textures.

#include <array>
#include <cstdint>

namespace viscera::textures {

/// 3D improved noise with a 256-entry permutation. Values lie in about [-1, 1] and equal those
/// of Perlin's reference implementation when built with the reference permutation.
class PerlinNoise {
 public:
  /// The reference permutation of Perlin 2002.
  PerlinNoise();
  /// A permutation shuffled from `seed` with the project's RNG (Fisher-Yates), for a
  /// different but equally distributed noise field per seed.
  explicit PerlinNoise(std::uint64_t seed);

  /// Noise at point (x, y, z); lattice spacing 1 in the point's units.
  double noise(double x, double y, double z) const;

  /// Sum of `octaves` octaves with frequency ×2 and amplitude × `persistence` per octave.
  double fractal_sum(double x, double y, double z, int octaves, double persistence = 0.5) const;
  /// Perlin's turbulence: the same sum of |noise|, in [0, ~1/(1-persistence)].
  double turbulence(double x, double y, double z, int octaves, double persistence = 0.5) const;

 private:
  std::array<std::uint8_t, 512> p_{};  ///< permutation repeated twice, so p_[i + 1] needs no wrap
};

}  // namespace viscera::textures
