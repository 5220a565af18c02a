#include "textures/texture_baker.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "core/primitives/icosphere.h"
#include "textures/png_io.h"
#include "textures/solid_texture.h"
#include "textures/surface_projector.h"
#include "textures/texture_preset.h"
#include "textures/triplanar_texture.h"
#include "textures/uv_atlas.h"

namespace viscera::textures {
namespace {

using core::Vec3;

/// Colour from position (a linear ramp) and the unperturbed normal: what lands in each texel
/// can be predicted exactly.
class PositionShader final : public SurfaceShader {
 public:
  SurfaceSample shade(const Vec3& p, const Vec3& n, double) const override {
    SurfaceSample s;
    s.albedo = {static_cast<float>(128.0 + 2500.0 * p.x()),
                static_cast<float>(128.0 + 2500.0 * p.y()),
                static_cast<float>(128.0 + 2500.0 * p.z())};
    s.normal = n;
    s.wetness = 0.25f;
    return s;
  }
};

TEST(TextureBaker, every_texel_inside_a_chart_shows_its_surface_point) {
  const auto atlas = build_uv_atlas(core::make_icosphere(0.04, 3), {256, 3});
  const auto maps = bake_surface_texture(atlas.mesh, PositionShader(), {256, 256, 3, 0});
  int checked = 0;
  // Sample triangle centroids: their texel must hold the colour of the centroid's position.
  for (const auto& t : atlas.mesh.triangles) {
    const core::Vec2 uv =
        (atlas.mesh.uvs[t[0]] + atlas.mesh.uvs[t[1]] + atlas.mesh.uvs[t[2]]) / 3.0;
    const Vec3 p =
        (atlas.mesh.vertices[t[0]] + atlas.mesh.vertices[t[1]] + atlas.mesh.vertices[t[2]]) / 3.0;
    const int x = static_cast<int>(uv.x() * 256), y = static_cast<int>((1.0 - uv.y()) * 256);
    const std::uint8_t* albedo = maps.albedo.row(y) + 3 * x;
    // Within the colour change across one texel (2500 · texel size ≈ 1.5 levels) plus rounding.
    for (int k = 0; k < 3; ++k)
      ASSERT_NEAR(albedo[k], 128.0 + 2500.0 * p[k], 3.0) << k;
    // An unperturbed normal is (0, 0, 1) in tangent space.
    const std::uint8_t* normal = maps.normal.row(y) + 3 * x;
    EXPECT_NEAR(normal[0], 128, 2);
    EXPECT_NEAR(normal[1], 128, 2);
    EXPECT_GE(normal[2], 253);
    EXPECT_NEAR(maps.specular.row(y)[x], 64, 1);
    ++checked;
  }
  EXPECT_EQ(checked, 1280);
}

TEST(TextureBaker, bakes_a_preset_deterministically_on_any_thread_count) {
  const auto atlas = build_uv_atlas(core::make_icosphere(0.04, 3), {256, 3});
  const auto& preset = find_texture_preset("myoma-surface");
  const SurfaceProjector surface(atlas.mesh);
  const SolidTissueTexture solid(preset, 5, 0.04, nullptr,
                                 grow_surface_vessels(preset, surface, 0.04, 5));
  const auto a = bake_surface_texture(atlas.mesh, solid, {256, 256, 3, 1});
  const auto b = bake_surface_texture(atlas.mesh, solid, {256, 256, 3, 4});
  EXPECT_EQ(encode_png(a.albedo), encode_png(b.albedo));
  EXPECT_EQ(encode_png(a.normal), encode_png(b.normal));
  EXPECT_EQ(encode_png(a.specular), encode_png(b.specular));
}

TEST(SolidTissueTexture, vessels_grown_on_a_surface_stay_on_it) {
  const auto sphere = core::make_icosphere(0.04, 4);
  const SurfaceProjector surface(sphere);
  const auto& preset = find_texture_preset("peritoneum");
  const auto layers = grow_surface_vessels(preset, surface, 0.05, 3);
  ASSERT_EQ(layers.size(), preset.vessels.size());
  ASSERT_FALSE(layers[0].empty());
  for (const auto& s : layers[0]) {
    // Chords between projected points dip below a sphere by at most l²/(8R).
    const double sag = (s.end - s.start).squaredNorm() / (8 * 0.04) + 2e-4;
    ASSERT_NEAR(s.end.norm(), 0.04, sag);
    ASSERT_NEAR((0.5 * (s.start + s.end)).norm(), 0.04, sag);
  }
  EXPECT_EQ(grow_surface_vessels(preset, surface, 0.05, 3)[0].back().end, layers[0].back().end);
}

TEST(SolidTissueTexture, bumps_tilt_the_normal_but_keep_it_facing_out) {
  const auto& preset = find_texture_preset("urethral-mucosa");
  const SolidTissueTexture solid(preset, 2, 0.03, nullptr);
  double tilt = 0.0;
  for (int i = 0; i < 200; ++i) {
    const Vec3 p(0.001 * i, 0.0003 * i, 0.01);
    const auto s = solid.shade(p, Vec3::UnitZ(), 1e-4);
    EXPECT_NEAR(s.normal.norm(), 1.0, 1e-12);
    EXPECT_GT(s.normal.z(), 0.3);
    tilt += 1.0 - s.normal.z();
  }
  EXPECT_GT(tilt, 0.0);
}

TEST(TriplanarTexture, projects_a_flat_map_along_the_dominant_axis) {
  TextureMaps maps;
  maps.albedo = Image8(4, 4, 3);
  // Left half red, right half blue (in u).
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x)
      maps.albedo.row(y)[3 * x + (x < 2 ? 0 : 2)] = 255;
  }
  const TriplanarTexture triplanar(maps, 0.04, 8.0);
  // On a face looking along +z, u is world x: x = 0.25 · 0.04 is in the red half.
  auto s = triplanar.shade(Vec3(0.25 * 0.04, 0.5 * 0.04, 0.0), Vec3::UnitZ(), 1e-3);
  EXPECT_NEAR(s.albedo[0], 255.0f, 1.0f);
  EXPECT_NEAR(s.albedo[2], 0.0f, 1.0f);
  s = triplanar.shade(Vec3(0.75 * 0.04 + 0.04, 0.5 * 0.04, 0.0), Vec3::UnitZ(), 1e-3);  // tiles
  EXPECT_NEAR(s.albedo[2], 255.0f, 1.0f);
  EXPECT_THROW(TriplanarTexture(TextureMaps{}, 0.04), core::UsageError);
}

TEST(TriplanarTexture, vertex_colors_for_surfaces_without_uvs) {
  auto sphere = core::make_icosphere(0.02, 2);
  bake_vertex_colors(sphere, PositionShader());
  ASSERT_EQ(sphere.vertex_attributes.at("albedo_r").size(), sphere.vertices.size());
  for (std::size_t v = 0; v < sphere.vertices.size(); ++v) {
    EXPECT_NEAR(sphere.vertex_attributes.at("albedo_g")[v],
                (128.0 + 2500.0 * sphere.vertices[v].y()) / 255.0, 1e-6);
    EXPECT_DOUBLE_EQ(sphere.vertex_attributes.at("wetness")[v], 0.25);
  }
}

}  // namespace
}  // namespace viscera::textures
