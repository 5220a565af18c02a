#include "core/random.h"

#include <cmath>

#include "core/error.h"

namespace viscera::core {
namespace {

// GCC's 128-bit integer; __extension__ marks the deliberate use under -Wpedantic.
__extension__ typedef unsigned __int128 UInt128;

constexpr std::uint64_t rotl(std::uint64_t x, int k) {
  return (x << k) | (x >> (64 - k));
}

}  // namespace

std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

Rng::Rng(std::uint64_t seed) {
  std::uint64_t s = seed;
  for (auto& word : state_)
    word = splitmix64(s);
}

Rng Rng::for_stream(std::uint64_t seed, std::uint64_t stream) {
  // Mix the stream index through SplitMix64 so neighbouring streams are unrelated.
  std::uint64_t s = stream ^ 0x5851f42d4c957f2dULL;
  return Rng(seed ^ splitmix64(s));
}

std::uint64_t Rng::next_u64() {
  const std::uint64_t result = rotl(state_[1] * 5, 7) * 9;
  const std::uint64_t t = state_[1] << 17;
  state_[2] ^= state_[0];
  state_[3] ^= state_[1];
  state_[1] ^= state_[2];
  state_[0] ^= state_[3];
  state_[2] ^= t;
  state_[3] = rotl(state_[3], 45);
  return result;
}

double Rng::uniform01() {
  return static_cast<double>(next_u64() >> 11) * 0x1.0p-53;
}

double Rng::uniform(double lo, double hi) {
  return lo + (hi - lo) * uniform01();
}

std::int64_t Rng::uniform_int(std::int64_t lo, std::int64_t hi) {
  if (hi < lo) throw UsageError("uniform_int needs lo <= hi");
  const std::uint64_t range = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
  if (range == ~std::uint64_t{0}) return static_cast<std::int64_t>(next_u64());
  const std::uint64_t span = range + 1;
  // Lemire 2019: multiply-shift with a rejection threshold removes the modulo bias.
  UInt128 product = static_cast<UInt128>(next_u64()) * span;
  auto low = static_cast<std::uint64_t>(product);
  if (low < span) {
    const std::uint64_t threshold = (0 - span) % span;
    while (low < threshold) {
      product = static_cast<UInt128>(next_u64()) * span;
      low = static_cast<std::uint64_t>(product);
    }
  }
  return lo + static_cast<std::int64_t>(product >> 64);
}

double Rng::normal(double mean, double stddev) {
  if (has_spare_normal_) {
    has_spare_normal_ = false;
    return mean + stddev * spare_normal_;
  }
  double u = 0.0, v = 0.0, s = 0.0;
  do {
    u = 2.0 * uniform01() - 1.0;
    v = 2.0 * uniform01() - 1.0;
    s = u * u + v * v;
  } while (s >= 1.0 || s == 0.0);
  const double factor = std::sqrt(-2.0 * std::log(s) / s);
  spare_normal_ = v * factor;
  has_spare_normal_ = true;
  return mean + stddev * u * factor;
}

double Rng::truncated_normal(double mean, double stddev, double lo, double hi) {
  if (!(lo < hi)) throw UsageError("truncated_normal needs lo < hi");
  if (stddev <= 0.0) return std::fmin(std::fmax(mean, lo), hi);
  for (int attempt = 0; attempt < 10000; ++attempt) {
    const double x = normal(mean, stddev);
    if (x >= lo && x <= hi) return x;
  }
  // The interval lies far in a tail: fall back to a uniform draw inside it, which is the
  // limit of the truncated density as the interval moves away from the mean.
  return uniform(lo, hi);
}

bool Rng::bernoulli(double p) {
  return uniform01() < p;
}

}  // namespace viscera::core
