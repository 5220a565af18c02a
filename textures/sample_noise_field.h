#pragma once
/// KisMo's turbulence from a sample image (seed 001 §3.3): "the noise field, which serves as a
/// basis for the turbulence function, is filled with pixel-values of a user defined image …
/// due to the random choice of pixels out of the sample, the final texture color is different
/// at each recalculation."

#include <array>
#include <cstdint>
#include <vector>

#include "textures/image8.h"

namespace viscera::textures {

using Rgb = std::array<float, 3>;  ///< sRGB values in [0, 255]

/// A smooth colour field whose lattice values are pixels drawn uniformly at random from a sample
/// image with the project's RNG. Octave o has its own lattice (4096 drawn colours, hashed by a
/// seeded permutation, so the field repeats only every 4096 cells) at frequency 2^o, rotated by
/// o·36.87° so the octaves' lattice lines never align (value noise otherwise shows its grid); the
/// colour is Σ_o a_o·V_o(2^o·R_o·p) / Σ_o a_o with a_o = persistence^o and V_o the quintic-
/// weighted interpolation of the lattice. Each value is a convex combination of drawn pixels, so
/// the field stays inside the sample's colour range and its expected colour is the sample's mean.
class SampleNoiseField {
 public:
  /// Draws the lattices from `sample` (RGB). Throws core::InputError when the sample is empty
  /// and core::UsageError when octaves is outside [1, 12].
  SampleNoiseField(const Image8& sample, std::uint64_t seed, int octaves = 3,
                   double persistence = 0.5);

  /// Colour at (x, y), lattice spacing 1 at the first octave.
  Rgb color(double x, double y) const;
  /// Colour at (x, y, z), for solid textures.
  Rgb color(double x, double y, double z) const;
  /// Highest lattice frequency (cells per unit length), for choosing a sampling grid.
  double top_frequency() const;

  int octaves() const { return static_cast<int>(lattices_.size()); }

 private:
  static constexpr int kLatticeSize = 4096;
  struct Lattice {
    std::vector<Rgb> colors;                 ///< kLatticeSize drawn sample pixels
    std::vector<std::uint16_t> permutation;  ///< kLatticeSize entries, twice, for hashing
    float weight = 1.0f;                     ///< a_o / Σ a
  };
  const Rgb& at(const Lattice& lattice, int x, int y) const;
  const Rgb& at(const Lattice& lattice, int x, int y, int z) const;

  std::vector<Lattice> lattices_;
};

/// An image of `count` pixels holding the palette colours in proportion to their weights, for
/// presets that have a palette instead of a user sample. Weights must be positive.
Image8 palette_sample(const std::vector<Rgb>& colors, const std::vector<double>& weights,
                      int count = 256);

}  // namespace viscera::textures
