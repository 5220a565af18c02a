// Noise and texture speed (docs/performance.md, "Textures and vessels"). Viscera's improved
// noise runs side by side with Debian's libnoise (libnoise-dev, module::Perlin) at the same
// octave count in the same run, so the ratio is measured, not quoted.

#include <benchmark/benchmark.h>
#include <libnoise/noise.h>

#include <vector>

#include "core/random.h"
#include "textures/perlin_noise.h"
#include "textures/texture_preset.h"
#include "textures/texture_synthesis.h"

namespace {

using viscera::textures::PerlinNoise;

constexpr int kPoints = 1 << 16;

/// Scattered sample points, the same for every benchmark.
const std::vector<double>& points() {
  static const std::vector<double> xyz = [] {
    viscera::core::Rng rng(1);
    std::vector<double> v(3 * kPoints);
    for (auto& c : v)
      c = rng.uniform(-100.0, 100.0);
    return v;
  }();
  return xyz;
}

// Point evaluation at scattered points: octaves = range(0).
void BM_ViscerasNoise3D_Points(benchmark::State& state) {
  const PerlinNoise noise;
  const int octaves = static_cast<int>(state.range(0));
  const auto& p = points();
  for (auto _ : state) {
    double sum = 0.0;
    for (int i = 0; i < kPoints; ++i) {
      sum += octaves == 1 ? noise.noise(p[3 * i], p[3 * i + 1], p[3 * i + 2])
                          : noise.fractal_sum(p[3 * i], p[3 * i + 1], p[3 * i + 2], octaves);
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * kPoints);
  state.counters["ns_per_sample"] = benchmark::Counter(
      static_cast<double>(kPoints) * 1e-9,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ViscerasNoise3D_Points)->Arg(1)->Arg(4);

void BM_Libnoise3D_Points(benchmark::State& state) {
  noise::module::Perlin perlin;
  perlin.SetOctaveCount(static_cast<int>(state.range(0)));
  perlin.SetPersistence(0.5);
  perlin.SetLacunarity(2.0);
  const auto& p = points();
  for (auto _ : state) {
    double sum = 0.0;
    for (int i = 0; i < kPoints; ++i)
      sum += perlin.GetValue(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * kPoints);
  state.counters["ns_per_sample"] = benchmark::Counter(
      static_cast<double>(kPoints) * 1e-9,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Libnoise3D_Points)->Arg(1)->Arg(4);

// Texture rows: 2048 samples spanning 32 lattice cells per row, as in a 2048² texture.
void BM_ViscerasNoise3D_Rows(benchmark::State& state) {
  const PerlinNoise noise;
  const int octaves = static_cast<int>(state.range(0));
  constexpr int kWidth = 2048, kRows = 64;
  std::vector<double> xs(kWidth), out(kWidth);
  for (int x = 0; x < kWidth; ++x)
    xs[x] = (x + 0.5) / kWidth * 32.0;
  for (auto _ : state) {
    for (int y = 0; y < kRows; ++y) {
      const double v = (y + 0.5) / kWidth * 32.0;
      if (octaves == 1) {
        noise.noise_row(xs.data(), kWidth, v, 0.37, out.data());
      } else {
        noise.turbulence_row(xs.data(), kWidth, v, 0.37, octaves, 0.5, out.data());
      }
      benchmark::DoNotOptimize(out.data());
    }
  }
  state.SetItemsProcessed(state.iterations() * kWidth * kRows);
  state.counters["ns_per_sample"] = benchmark::Counter(
      static_cast<double>(kWidth * kRows) * 1e-9,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ViscerasNoise3D_Rows)->Arg(1)->Arg(4);

void BM_Libnoise3D_Rows(benchmark::State& state) {
  noise::module::Perlin perlin;
  perlin.SetOctaveCount(static_cast<int>(state.range(0)));
  constexpr int kWidth = 2048, kRows = 64;
  std::vector<double> out(kWidth);
  for (auto _ : state) {
    for (int y = 0; y < kRows; ++y) {
      const double v = (y + 0.5) / kWidth * 32.0;
      for (int x = 0; x < kWidth; ++x)
        out[x] = perlin.GetValue((x + 0.5) / kWidth * 32.0, v, 0.37);
      benchmark::DoNotOptimize(out.data());
    }
  }
  state.SetItemsProcessed(state.iterations() * kWidth * kRows);
  state.counters["ns_per_sample"] = benchmark::Counter(
      static_cast<double>(kWidth * kRows) * 1e-9,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Libnoise3D_Rows)->Arg(1)->Arg(4);

// A 2048² tissue texture: four-octave turbulence grain, sample colour field and vessels.
// range(0) = 0: albedo only (the target); 1: albedo, normal and specular maps.
void BM_TissueTexture2048(benchmark::State& state) {
  const auto& preset = viscera::textures::find_texture_preset("endometrium");
  viscera::textures::TextureOptions options;
  options.width = options.height = 2048;
  options.seed = 7;
  options.normal_and_specular = state.range(0) != 0;
  for (auto _ : state) {
    const auto maps = viscera::textures::synthesize_texture(preset, options);
    benchmark::DoNotOptimize(maps.albedo.pixels.data());
  }
}
BENCHMARK(BM_TissueTexture2048)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
