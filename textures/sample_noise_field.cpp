#include "textures/sample_noise_field.h"

#include <cmath>
#include <numeric>

#include "core/error.h"
#include "core/random.h"

namespace viscera::textures {
namespace {

constexpr int kMask = 4095;

inline float fade(float t) {
  return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

inline Rgb mix(const Rgb& a, const Rgb& b, float t) {
  return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

}  // namespace

SampleNoiseField::SampleNoiseField(const Image8& sample, std::uint64_t seed, int octaves,
                                   double persistence) {
  if (sample.empty() || sample.channels != 3) {
    throw core::InputError("the sample image has no RGB pixels");
  }
  if (octaves < 1 || octaves > 12)
    throw core::UsageError("sample noise octaves must be in [1, 12]");
  const auto pixel_count = static_cast<std::int64_t>(sample.width) * sample.height;
  double total = 0.0, amplitude = 1.0;
  for (int o = 0; o < octaves; ++o, amplitude *= persistence)
    total += amplitude;
  amplitude = 1.0;
  for (int o = 0; o < octaves; ++o, amplitude *= persistence) {
    // One independent stream per octave: adding octaves never changes the lower ones.
    core::Rng rng = core::Rng::for_stream(seed, static_cast<std::uint64_t>(o));
    Lattice lattice;
    lattice.weight = static_cast<float>(amplitude / total);
    lattice.colors.resize(kLatticeSize);
    for (auto& color : lattice.colors) {
      const auto index = static_cast<std::size_t>(rng.uniform_int(0, pixel_count - 1)) * 3;
      color = {static_cast<float>(sample.pixels[index]),
               static_cast<float>(sample.pixels[index + 1]),
               static_cast<float>(sample.pixels[index + 2])};
    }
    std::vector<std::uint16_t> permutation(kLatticeSize);
    std::iota(permutation.begin(), permutation.end(), std::uint16_t{0});
    for (int i = kLatticeSize - 1; i > 0; --i) {
      std::swap(permutation[i], permutation[rng.uniform_int(0, i)]);
    }
    lattice.permutation.resize(2 * kLatticeSize);
    for (int i = 0; i < 2 * kLatticeSize; ++i)
      lattice.permutation[i] = permutation[i & kMask];
    lattices_.push_back(std::move(lattice));
  }
}

const Rgb& SampleNoiseField::at(const Lattice& l, int x, int y) const {
  // Negative coordinates wrap through the mask like positive ones.
  return l.colors[l.permutation[l.permutation[x & kMask] + (y & kMask)]];
}

const Rgb& SampleNoiseField::at(const Lattice& l, int x, int y, int z) const {
  const auto& p = l.permutation;
  return l.colors[p[p[p[x & kMask] + (y & kMask)] + (z & kMask)]];
}

namespace {

/// Rotation of octave o: o·atan(3/4) about z in the plane, and about the (1,1,1) axis in space;
/// both irrational in turns, so no two octaves share lattice directions.
constexpr double kOctaveAngle = 0.6435011087932844;

void rotate_2d(int octave, double& x, double& y) {
  const double a = kOctaveAngle * octave;
  const double c = std::cos(a), s = std::sin(a);
  const double rx = c * x - s * y;
  y = s * x + c * y;
  x = rx;
}

void rotate_3d(int octave, double& x, double& y, double& z) {
  // Rodrigues about the unit (1,1,1)/√3 axis.
  const double a = kOctaveAngle * octave;
  const double c = std::cos(a), s = std::sin(a), k = 1.0 / std::sqrt(3.0);
  const double dot = k * (x + y + z);
  const double cx = k * (y - z), cy = k * (z - x), cz = k * (x - y);  // axis × p
  const double rx = x * c + cx * s + k * dot * (1.0 - c);
  const double ry = y * c + cy * s + k * dot * (1.0 - c);
  const double rz = z * c + cz * s + k * dot * (1.0 - c);
  x = rx;
  y = ry;
  z = rz;
}

}  // namespace

Rgb SampleNoiseField::color(double x, double y) const {
  Rgb sum{0.0f, 0.0f, 0.0f};
  double frequency = 1.0;
  for (std::size_t o = 0; o < lattices_.size(); ++o) {
    const auto& lattice = lattices_[o];
    double sx = x * frequency, sy = y * frequency;
    rotate_2d(static_cast<int>(o), sx, sy);
    const double fx = std::floor(sx), fy = std::floor(sy);
    const int X = static_cast<int>(fx), Y = static_cast<int>(fy);
    const float u = fade(static_cast<float>(sx - fx)), v = fade(static_cast<float>(sy - fy));
    const Rgb c = mix(mix(at(lattice, X, Y), at(lattice, X + 1, Y), u),
                      mix(at(lattice, X, Y + 1), at(lattice, X + 1, Y + 1), u), v);
    for (int k = 0; k < 3; ++k)
      sum[k] += lattice.weight * c[k];
    frequency *= 2.0;
  }
  return sum;
}

Rgb SampleNoiseField::color(double x, double y, double z) const {
  Rgb sum{0.0f, 0.0f, 0.0f};
  double frequency = 1.0;
  for (std::size_t o = 0; o < lattices_.size(); ++o) {
    const auto& lattice = lattices_[o];
    double sx = x * frequency, sy = y * frequency, sz = z * frequency;
    rotate_3d(static_cast<int>(o), sx, sy, sz);
    const double fx = std::floor(sx), fy = std::floor(sy), fz = std::floor(sz);
    const int X = static_cast<int>(fx), Y = static_cast<int>(fy), Z = static_cast<int>(fz);
    const float u = fade(static_cast<float>(sx - fx)), v = fade(static_cast<float>(sy - fy)),
                w = fade(static_cast<float>(sz - fz));
    const Rgb near = mix(mix(at(lattice, X, Y, Z), at(lattice, X + 1, Y, Z), u),
                         mix(at(lattice, X, Y + 1, Z), at(lattice, X + 1, Y + 1, Z), u), v);
    const Rgb far = mix(mix(at(lattice, X, Y, Z + 1), at(lattice, X + 1, Y, Z + 1), u),
                        mix(at(lattice, X, Y + 1, Z + 1), at(lattice, X + 1, Y + 1, Z + 1), u), v);
    const Rgb c = mix(near, far, w);
    for (int k = 0; k < 3; ++k)
      sum[k] += lattice.weight * c[k];
    frequency *= 2.0;
  }
  return sum;
}

double SampleNoiseField::top_frequency() const {
  return std::ldexp(1.0, static_cast<int>(lattices_.size()) - 1);
}

Image8 palette_sample(const std::vector<Rgb>& colors, const std::vector<double>& weights,
                      int count) {
  if (colors.empty() || colors.size() != weights.size()) {
    throw core::UsageError("a palette needs one positive weight per colour");
  }
  const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
  for (const double w : weights) {
    if (!(w > 0.0)) throw core::UsageError("palette weights must be positive");
  }
  Image8 image(count, 1, 3);
  // Cumulative rounding gives each colour its share of the pixels, every colour at least one.
  double cumulative = 0.0;
  int pixel = 0;
  for (std::size_t c = 0; c < colors.size(); ++c) {
    cumulative += weights[c];
    int end = static_cast<int>(std::lround(cumulative / total * count));
    end = std::max(end, pixel + 1);
    if (c + 1 == colors.size()) end = count;
    for (; pixel < end && pixel < count; ++pixel) {
      for (int k = 0; k < 3; ++k) {
        image.pixels[3 * pixel + k] = static_cast<std::uint8_t>(
            std::lround(std::fmin(255.0f, std::fmax(0.0f, colors[c][k]))));
      }
    }
  }
  return image;
}

}  // namespace viscera::textures
