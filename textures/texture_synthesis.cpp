#include "textures/texture_synthesis.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/random.h"
#include "textures/parallel_rows.h"
#include "textures/perlin_noise.h"
#include "textures/sample_noise_field.h"
#include "textures/tissue_shading.h"
#include "textures/vessel_painter.h"

namespace viscera::textures {
namespace {

// Seed streams: each field draws from its own stream, so changing one never shifts another.
constexpr std::uint64_t kColorStream = 0, kGrainStream = 1, kWetnessStream = 2, kVesselStream = 16;

/// Rounds to the nearest byte (halves up); adding 0.5 and truncating avoids a libm call per
/// channel, which mattered in profiles of 2048² textures.
inline std::uint8_t to_byte(float value) {
  return static_cast<std::uint8_t>(std::clamp(value, 0.0f, 255.0f) + 0.5f);
}

double amplitude_sum(int octaves, double persistence) {
  double sum = 0.0, amplitude = 1.0;
  for (int o = 0; o < octaves; ++o, amplitude *= persistence)
    sum += amplitude;
  return sum;
}

/// The colour field sampled every `spacing` pixels and interpolated bilinearly in between. The
/// field is smooth at that scale (at least 8 samples per cell of its finest octave), so a few
/// thousand exact evaluations stand in for millions.
class ColorGrid {
 public:
  ColorGrid(const SampleNoiseField& field, double frequency, int width, int height, int threads) {
    const double finest_cell_px = width / (frequency * field.top_frequency());
    spacing_ = std::clamp(static_cast<int>(finest_cell_px / 8.0), 1, 16);
    nx_ = (width - 1) / spacing_ + 2;
    ny_ = (height - 1) / spacing_ + 2;
    nodes_.resize(3 * static_cast<std::size_t>(nx_) * ny_);
    for (int s = 0; s < spacing_; ++s)
      weights_.push_back(static_cast<float>(s) / static_cast<float>(spacing_));
    parallel_rows(
        ny_,
        [&](int begin, int end) {
          for (int j = begin; j < end; ++j) {
            for (int i = 0; i < nx_; ++i) {
              const Rgb c = field.color((i * spacing_ + 0.5) / width * frequency,
                                        (j * spacing_ + 0.5) / width * frequency);
              std::copy(c.begin(), c.end(),
                        nodes_.begin() + 3 * (static_cast<std::ptrdiff_t>(j) * nx_ + i));
            }
          }
        },
        threads);
  }

  /// Interleaved RGB of pixel row y into rgb (3 × width floats); row_buffer holds 3·nx floats.
  void row(int y, int width, float* rgb, std::vector<float>& row_buffer) const {
    row_buffer.resize(3 * static_cast<std::size_t>(nx_));
    const int j = y / spacing_;
    const float ty = static_cast<float>(y - j * spacing_) / static_cast<float>(spacing_);
    const float* top = nodes_.data() + 3 * static_cast<std::size_t>(j) * nx_;
    const float* bottom = top + 3 * static_cast<std::size_t>(nx_);
    for (int k = 0; k < 3 * nx_; ++k)
      row_buffer[k] = top[k] + ty * (bottom[k] - top[k]);
    // Each node interval spans `spacing_` pixels with the same weights: no division per pixel.
    for (int i = 0, x = 0; x < width; ++i) {
      const float* a = row_buffer.data() + 3 * i;
      for (int s = 0; s < spacing_ && x < width; ++s, ++x) {
        const float tx = weights_[s];
        rgb[3 * x + 0] = a[0] + tx * (a[3] - a[0]);
        rgb[3 * x + 1] = a[1] + tx * (a[4] - a[1]);
        rgb[3 * x + 2] = a[2] + tx * (a[5] - a[2]);
      }
    }
  }

 private:
  int spacing_ = 1, nx_ = 0, ny_ = 0;
  std::vector<float> nodes_;
  std::vector<float> weights_;  ///< s / spacing for s < spacing
};

}  // namespace

Image8 normal_map_from_height(const std::vector<float>& h, int width, int height, double strength,
                              int threads) {
  Image8 normal(width, height, 3);
  // Differences per pixel → per texture width: × width / 2 for central differences.
  const auto scale = static_cast<float>(strength * width * 0.5);
  parallel_rows(
      height,
      [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
          const float* above = h.data() + static_cast<std::size_t>(std::max(y - 1, 0)) * width;
          const float* below =
              h.data() + static_cast<std::size_t>(std::min(y + 1, height - 1)) * width;
          const float* row = h.data() + static_cast<std::size_t>(y) * width;
          std::uint8_t* out = normal.row(y);
          for (int x = 0; x < width; ++x) {
            const float du = row[std::min(x + 1, width - 1)] - row[std::max(x - 1, 0)];
            const float dv = above[x] - below[x];  // rows go down the image, +v goes up
            const float nx = -scale * du, ny = -scale * dv;
            const float inverse_length = 1.0f / std::sqrt(nx * nx + ny * ny + 1.0f);
            out[3 * x + 0] = to_byte((nx * inverse_length + 1.0f) * 127.5f);
            out[3 * x + 1] = to_byte((ny * inverse_length + 1.0f) * 127.5f);
            out[3 * x + 2] = to_byte((inverse_length + 1.0f) * 127.5f);
          }
        }
      },
      threads);
  return normal;
}

TextureMaps synthesize_texture(const TexturePreset& preset, const TextureOptions& options,
                               core::Progress& progress) {
  const int width = options.width, height = options.height;
  if (width < 8 || height < 8 || width > 16384 || height > 16384) {
    throw core::UsageError("texture size must be between 8 and 16384 pixels per side");
  }
  const std::size_t pixel_count = static_cast<std::size_t>(width) * height;
  const int layer_count = options.vessels ? static_cast<int>(preset.vessels.size()) : 0;
  progress.begin_stage("texture " + preset.name, 2 + layer_count);

  const Image8 palette = palette_sample(preset.palette, preset.palette_weights);
  const SampleNoiseField colors(options.sample ? *options.sample : palette,
                                core::Rng::for_stream(options.seed, kColorStream).next_u64(),
                                preset.color_octaves, preset.color_persistence);
  const PerlinNoise grain(core::Rng::for_stream(options.seed, kGrainStream).next_u64());
  const PerlinNoise wetness(core::Rng::for_stream(options.seed, kWetnessStream).next_u64());

  std::vector<VesselRasterizer> layers;
  for (int l = 0; l < layer_count; ++l) {
    layers.emplace_back(
        grow_vessel_layer(preset.vessels[l], width, height,
                          core::Rng::for_stream(options.seed, kVesselStream + l).next_u64()),
        width, height);
    progress.step();
  }

  // Sample coordinates in texture widths × frequency, shared by every row.
  const auto coordinates = [width](double frequency) {
    std::vector<double> xs(static_cast<std::size_t>(width));
    for (int x = 0; x < width; ++x)
      xs[x] = (x + 0.5) / width * frequency;
    return xs;
  };
  const ColorGrid color_grid(colors, preset.color_frequency, width, height, options.threads);
  const std::vector<double> grain_xs = coordinates(preset.grain_frequency);
  const std::vector<double> wet_xs = coordinates(preset.specular_frequency);
  const double grain_norm = 1.0 / amplitude_sum(preset.grain_octaves, preset.grain_persistence);
  const double wet_norm = 1.0 / amplitude_sum(3, 0.5);

  TextureMaps maps;
  maps.albedo = Image8(width, height, 3);
  std::vector<float> height_field(options.normal_and_specular ? pixel_count : 0);
  if (options.normal_and_specular) maps.specular = Image8(width, height, 1);

  // Vessels are painted a few rows at a time just before those rows are composed, so no
  // full-size coverage buffer is ever allocated or zeroed.
  constexpr int kChunkRows = 16;
  parallel_rows(
      height,
      [&](int begin, int end) {
        std::vector<float> rgb(3 * static_cast<std::size_t>(width)), albedo_rgb(rgb.size()),
            grid_row;
        std::vector<float> heights(width), wet_values(width);
        std::vector<double> turbulence(width), wet(width);
        const std::size_t chunk_size = static_cast<std::size_t>(kChunkRows) * width;
        std::vector<float> chunk_coverage(layers.size() * chunk_size),
            chunk_depth(chunk_coverage.size());
        std::vector<const float*> coverage(layers.size()), depth(layers.size());
        for (int chunk = begin; chunk < end; chunk += kChunkRows) {
          const int chunk_end = std::min(end, chunk + kChunkRows);
          std::fill(chunk_coverage.begin(), chunk_coverage.end(), 0.0f);
          std::fill(chunk_depth.begin(), chunk_depth.end(), 0.0f);
          for (std::size_t l = 0; l < layers.size(); ++l) {
            layers[l].paint_rows(chunk, chunk_end, chunk_coverage.data() + l * chunk_size,
                                 chunk_depth.data() + l * chunk_size);
          }
          for (int y = chunk; y < chunk_end; ++y) {
            const double v = (y + 0.5) / width;  // texture widths, so texels stay square
            color_grid.row(y, width, rgb.data(), grid_row);
            grain.turbulence_row(grain_xs.data(), width,
                                 v * preset.grain_frequency * preset.grain_aspect,
                                 preset.grain_octaves, preset.grain_persistence, turbulence.data());
            if (options.normal_and_specular) {
              wetness.fractal_row(wet_xs.data(), width, v * preset.specular_frequency, 3, 0.5,
                                  wet.data());
            }
            const std::size_t chunk_row = static_cast<std::size_t>(y - chunk) * width;
            for (std::size_t l = 0; l < layers.size(); ++l) {
              coverage[l] = chunk_coverage.data() + l * chunk_size + chunk_row;
              depth[l] = chunk_depth.data() + l * chunk_size + chunk_row;
            }
            TissueFields fields;
            fields.count = width;
            fields.base_rgb = rgb.data();
            fields.turbulence = turbulence.data();
            fields.turbulence_scale = grain_norm;
            fields.wetness_noise = options.normal_and_specular ? wet.data() : nullptr;
            fields.wetness_scale = wet_norm;
            fields.coverage = coverage.data();
            fields.depth = depth.data();
            shade_tissue(preset, fields, albedo_rgb.data(), heights.data(), wet_values.data());
            std::uint8_t* albedo = maps.albedo.row(y);
            for (int i = 0; i < 3 * width; ++i)
              albedo[i] = to_byte(albedo_rgb[i]);
            if (options.normal_and_specular) {
              const std::size_t row_start = static_cast<std::size_t>(y) * width;
              std::copy(heights.begin(), heights.end(),
                        height_field.begin() + static_cast<std::ptrdiff_t>(row_start));
              for (int x = 0; x < width; ++x) {
                maps.specular.pixels[row_start + x] = to_byte(wet_values[x] * 255.0f);
              }
            }
          }
        }
      },
      options.threads);
  progress.step();

  if (options.normal_and_specular) {
    maps.normal = normal_map_from_height(height_field, width, height, preset.normal_strength,
                                         options.threads);
  }
  progress.step();
  return maps;
}

}  // namespace viscera::textures
