#include "textures/sample_noise_field.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "core/error.h"
#include "core/random.h"
#include "textures/texture_preset.h"
#include "textures/texture_synthesis.h"

namespace viscera::textures {
namespace {

/// A 64×64 sample: 30 % dark red, 70 % pale pink pixels scattered at random.
Image8 two_colour_sample() {
  Image8 sample(64, 64, 3);
  core::Rng rng(99);
  for (int i = 0; i < 64 * 64; ++i) {
    const bool dark = rng.bernoulli(0.3);
    sample.pixels[3 * i + 0] = dark ? 150 : 235;
    sample.pixels[3 * i + 1] = dark ? 30 : 190;
    sample.pixels[3 * i + 2] = dark ? 40 : 185;
  }
  return sample;
}

std::array<double, 3> mean_color(const Image8& image) {
  std::array<double, 3> sum{0, 0, 0};
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    sum[i % 3] += image.pixels[i];
  for (auto& s : sum)
    s /= static_cast<double>(image.pixels.size() / 3);
  return sum;
}

TEST(SampleNoiseField, colour_statistics_follow_the_sample) {
  const Image8 sample = two_colour_sample();
  const auto expected = mean_color(sample);
  const SampleNoiseField field(sample, 5, 3, 0.5);
  std::array<double, 3> sum{0, 0, 0};
  const int n = 400;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const Rgb c = field.color(i * 0.173, j * 0.173);
      for (int k = 0; k < 3; ++k) {
        // Convex combinations of sample pixels stay inside the sample's range.
        ASSERT_GE(c[k], (k == 0 ? 150.0f : k == 1 ? 30.0f : 40.0f) - 1e-3f);
        ASSERT_LE(c[k], (k == 0 ? 235.0f : k == 1 ? 190.0f : 185.0f) + 1e-3f);
        sum[k] += static_cast<double>(c[k]);
      }
    }
  }
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(sum[k] / (n * n), expected[k], 4.0) << "channel " << k;
}

TEST(SampleNoiseField, solid_field_follows_the_sample_too) {
  const Image8 sample = two_colour_sample();
  const auto expected = mean_color(sample);
  const SampleNoiseField field(sample, 6, 3, 0.5);
  core::Rng rng(1);
  std::array<double, 3> sum{0, 0, 0};
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const Rgb c = field.color(rng.uniform(0, 300), rng.uniform(0, 300), rng.uniform(0, 300));
    for (int k = 0; k < 3; ++k)
      sum[k] += static_cast<double>(c[k]);
  }
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(sum[k] / n, expected[k], 3.0) << "channel " << k;
}

TEST(SampleNoiseField, differs_for_every_seed_and_repeats_for_the_same) {
  const Image8 sample = two_colour_sample();
  const SampleNoiseField a(sample, 1), b(sample, 1), c(sample, 2);
  EXPECT_EQ(a.color(3.3, 4.4), b.color(3.3, 4.4));
  EXPECT_NE(a.color(3.3, 4.4), c.color(3.3, 4.4));
}

TEST(SampleNoiseField, refuses_an_empty_sample) {
  EXPECT_THROW(SampleNoiseField(Image8(), 1), core::InputError);
}

TEST(SampleNoiseField, palette_sample_holds_colours_in_proportion) {
  const Image8 palette = palette_sample({{255, 0, 0}, {0, 0, 255}}, {3.0, 1.0}, 100);
  int red = 0;
  for (int i = 0; i < 100; ++i)
    red += palette.pixels[3 * i] == 255;
  EXPECT_EQ(red, 75);
}

TEST(TextureSynthesis, texture_from_a_sample_takes_its_colours) {
  const Image8 sample = two_colour_sample();
  const auto expected = mean_color(sample);
  TextureOptions options;
  options.width = options.height = 256;
  options.sample = &sample;
  options.vessels = false;
  options.normal_and_specular = false;
  for (const auto& name : texture_preset_names()) {
    const auto& preset = find_texture_preset(name);
    const auto mean = mean_color(synthesize_texture(preset, options).albedo);
    // Grain scales brightness around its mean, so the mean colour stays the sample's within a
    // few percent.
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(mean[k], expected[k], 0.06 * expected[k]) << name << " " << k;
  }
}

}  // namespace
}  // namespace viscera::textures
