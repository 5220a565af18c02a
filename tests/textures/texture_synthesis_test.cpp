#include "textures/texture_synthesis.h"

#include <gtest/gtest.h>

#include <numeric>

#include "core/error.h"
#include "textures/png_io.h"
#include "textures/texture_preset.h"
#include "textures/vessel_painter.h"

namespace viscera::textures {
namespace {

TextureOptions small(std::uint64_t seed) {
  TextureOptions options;
  options.seed = seed;
  options.width = 192;
  options.height = 128;
  return options;
}

TEST(TexturePresets, the_five_presets_of_the_issue_are_built_in_and_round_trip) {
  const std::vector<std::string> expected = {"endometrium", "myoma-surface", "peritoneum", "liver",
                                             "urethral-mucosa"};
  EXPECT_EQ(texture_preset_names(), expected);
  for (const auto& name : expected) {
    const auto& preset = find_texture_preset(name);
    EXPECT_FALSE(preset.vessels.empty()) << name;
    const auto again = texture_preset_from_json(texture_preset_to_json(preset), name);
    EXPECT_EQ(texture_preset_to_json(again), texture_preset_to_json(preset)) << name;
  }
  EXPECT_THROW(find_texture_preset("spleen"), core::UsageError);
}

TEST(TexturePresets, a_bad_member_is_reported_with_its_json_pointer) {
  auto json = texture_preset_to_json(find_texture_preset("liver"));
  json["vessels"][0]["opacity"] = 3.0;
  try {
    texture_preset_from_json(json, "liver", "/presets/3");
    FAIL();
  } catch (const core::ValidationError& e) {
    EXPECT_EQ(e.location().json_pointer, "/presets/3/vessels/0/opacity");
  }
  json = texture_preset_to_json(find_texture_preset("liver"));
  json["vessels"][0]["grammar"] = "A -> B";
  EXPECT_THROW(texture_preset_from_json(json, "liver"), core::ValidationError);
}

TEST(TextureSynthesis, same_seed_gives_the_same_png_bytes_for_every_preset) {
  for (const auto& name : texture_preset_names()) {
    const auto& preset = find_texture_preset(name);
    const TextureMaps a = synthesize_texture(preset, small(7));
    const TextureMaps b = synthesize_texture(preset, small(7));
    EXPECT_EQ(encode_png(a.albedo), encode_png(b.albedo)) << name;
    EXPECT_EQ(encode_png(a.normal), encode_png(b.normal)) << name;
    EXPECT_EQ(encode_png(a.specular), encode_png(b.specular)) << name;
    EXPECT_NE(encode_png(synthesize_texture(preset, small(8)).albedo), encode_png(a.albedo))
        << name;
  }
}

TEST(TextureSynthesis, thread_count_never_changes_a_pixel) {
  const auto& preset = find_texture_preset("endometrium");
  TextureOptions one = small(3), many = small(3);
  one.threads = 1;
  many.threads = 5;
  const auto a = synthesize_texture(preset, one), b = synthesize_texture(preset, many);
  EXPECT_EQ(a.albedo, b.albedo);
  EXPECT_EQ(a.normal, b.normal);
  EXPECT_EQ(a.specular, b.specular);
}

TEST(TextureSynthesis, maps_have_the_documented_shapes_and_ranges) {
  const auto maps = synthesize_texture(find_texture_preset("peritoneum"), small(2));
  EXPECT_EQ(maps.albedo.channels, 3);
  EXPECT_EQ(maps.specular.channels, 1);
  EXPECT_EQ(maps.normal.width, 192);
  EXPECT_EQ(maps.normal.height, 128);
  // Tangent-space normals point out of the surface: blue (z) above 0.5 everywhere.
  for (std::size_t i = 2; i < maps.normal.pixels.size(); i += 3)
    ASSERT_GT(maps.normal.pixels[i], 128);
  // A wet peritoneum: mean specular near the preset's base of 0.75.
  const double mean =
      std::accumulate(maps.specular.pixels.begin(), maps.specular.pixels.end(), 0.0) /
      static_cast<double>(maps.specular.pixels.size());
  EXPECT_NEAR(mean / 255.0, 0.75, 0.08);
}

TEST(TextureSynthesis, vessels_darken_the_albedo_where_they_run) {
  const auto& preset = find_texture_preset("myoma-surface");
  TextureOptions with = small(4), without = small(4);
  without.vessels = false;
  const auto a = synthesize_texture(preset, with).albedo;
  const auto b = synthesize_texture(preset, without).albedo;
  const double sum_a = std::accumulate(a.pixels.begin(), a.pixels.end(), 0.0);
  const double sum_b = std::accumulate(b.pixels.begin(), b.pixels.end(), 0.0);
  EXPECT_LT(sum_a, sum_b);  // red vessels over pale tissue
}

TEST(TextureSynthesis, refuses_sizes_outside_the_documented_range) {
  TextureOptions options = small(1);
  options.width = 4;
  EXPECT_THROW(synthesize_texture(find_texture_preset("liver"), options), core::UsageError);
}

TEST(NormalMap, a_ramp_tilts_normals_against_its_slope) {
  std::vector<float> height(16 * 16);
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x)
      height[y * 16 + x] = static_cast<float>(x) / 16.0f;  // h = u
  }
  const Image8 normal = normal_map_from_height(height, 16, 16, 1.0);
  // ∂h/∂u = 1 per texture width → n = (−1, 0, 1)/√2 → about (37, 128, 218).
  const std::uint8_t* p = normal.row(8) + 3 * 8;
  EXPECT_NEAR(p[0], 37, 1);
  EXPECT_NEAR(p[1], 128, 1);
  EXPECT_NEAR(p[2], 218, 1);
}

TEST(VesselPainter, paints_an_antialiased_tapered_stroke) {
  core::TurtleSegment s;
  s.start = {10, 32, 0};
  s.end = {110, 32, 0};
  s.start_width = 8;
  s.end_width = 2;
  const auto layer = paint_vessels({s}, 128, 64, 2);
  const auto at = [&](int x, int y) { return layer.coverage[y * 128 + x]; };
  EXPECT_FLOAT_EQ(at(20, 31), 1.0f);
  EXPECT_FLOAT_EQ(at(20, 20), 0.0f);
  EXPECT_FLOAT_EQ(at(120, 31), 0.0f);
  const auto column_ink = [&](int x) {
    float sum = 0;
    for (int y = 0; y < 64; ++y)
      sum += at(x, y);
    return sum;
  };
  EXPECT_NEAR(column_ink(15), 7.7, 0.5);   // width 7.7 there
  EXPECT_NEAR(column_ink(100), 2.6, 0.5);  // width 2.6 there
  EXPECT_GT(column_ink(15), column_ink(60));
  EXPECT_GT(column_ink(60), column_ink(100));
}

TEST(VesselPainter, vessel_layers_are_deterministic_per_seed) {
  const auto& spec = find_texture_preset("endometrium").vessels[0];
  const auto a = grow_vessel_layer(spec, 512, 512, 9);
  const auto b = grow_vessel_layer(spec, 512, 512, 9);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_FALSE(a.empty());
  for (std::size_t i = 0; i < a.size(); ++i)
    ASSERT_TRUE(a[i].end == b[i].end);
  EXPECT_FALSE(grow_vessel_layer(spec, 512, 512, 10).back().end == a.back().end);
  EXPECT_EQ(paint_vessels(a, 512, 512, 1).coverage, paint_vessels(a, 512, 512, 3).coverage);
}

}  // namespace
}  // namespace viscera::textures
