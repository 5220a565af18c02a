#pragma once
/// The project's seeded random number generator and its own distributions. Standard library
/// distributions differ between implementations, so every draw in Viscera goes through these:
/// the same seed gives the same bytes with any compiler and standard library (DESIGN.md §7).
/// Engine: xoshiro256** 1.0 (Blackman & Vigna 2018), seeded through SplitMix64.

#include <array>
#include <cstdint>

namespace viscera::core {

/// Deterministic pseudo-random generator with portable distributions.
class Rng {
 public:
  /// Seeds the four state words from `seed` with SplitMix64, as the xoshiro authors advise.
  explicit Rng(std::uint64_t seed = 0);

  /// A generator for sub-stream `stream` of `seed` (e.g. patient k of a batch), independent of
  /// how many numbers other streams drew.
  static Rng for_stream(std::uint64_t seed, std::uint64_t stream);

  /// Next raw 64-bit output.
  std::uint64_t next_u64();
  /// Uniform double in [0, 1) with 53 random bits.
  double uniform01();
  /// Uniform double in [lo, hi).
  double uniform(double lo, double hi);
  /// Uniform integer in [lo, hi] without modulo bias (Lemire's method with rejection).
  std::int64_t uniform_int(std::int64_t lo, std::int64_t hi);
  /// Normal deviate with the given mean and standard deviation (Marsaglia polar method;
  /// the spare deviate is kept so two draws cost one rejection loop).
  double normal(double mean, double stddev);
  /// Normal deviate restricted to [lo, hi] by rejection; lo < hi required.
  double truncated_normal(double mean, double stddev, double lo, double hi);
  /// True with probability p.
  bool bernoulli(double p);

 private:
  std::array<std::uint64_t, 4> state_{};
  bool has_spare_normal_ = false;
  double spare_normal_ = 0.0;
};

/// SplitMix64 step: advances `state` and returns a well-mixed 64-bit value.
std::uint64_t splitmix64(std::uint64_t& state);

}  // namespace viscera::core
