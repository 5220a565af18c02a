#include "textures/uv_atlas.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "core/primitives/icosphere.h"
#include "textures/uv_charts.h"

namespace viscera::textures {
namespace {

/// A closed torus (genus 1): no single cut makes it a disk, so charts must handle it.
core::SurfaceMesh torus(double major, double minor, int nu, int nv) {
  core::SurfaceMesh mesh;
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * std::numbers::pi * i / nu, v = 2 * std::numbers::pi * j / nv;
      mesh.vertices.emplace_back((major + minor * std::cos(v)) * std::cos(u),
                                 (major + minor * std::cos(v)) * std::sin(u), minor * std::sin(v));
    }
  }
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const int a = i * nv + j, b = ((i + 1) % nu) * nv + j, c = ((i + 1) % nu) * nv + (j + 1) % nv,
                d = i * nv + (j + 1) % nv;
      mesh.triangles.push_back({a, b, c});
      mesh.triangles.push_back({a, c, d});
    }
  }
  return mesh;
}

/// The stated bounds of docs/performance.md ("UV atlas distortion"): LSCM charts of organ-like
/// closed surfaces stay near-isometric.
void expect_within_stated_bounds(const UvDistortion& d) {
  EXPECT_EQ(d.flipped, 0);
  EXPECT_LT(d.l2_stretch, 1.05);
  EXPECT_LT(d.mean_conformal, 1.05);
  EXPECT_LT(d.max_conformal, 1.5);
  EXPECT_GT(d.area_ratio_p05, 0.75);
  EXPECT_LT(d.area_ratio_p95, 1.33);
}

void expect_valid_atlas(const core::SurfaceMesh& input, const UvAtlas& atlas) {
  ASSERT_EQ(atlas.mesh.triangles.size(), input.triangles.size());
  ASSERT_EQ(atlas.original_vertex.size(), atlas.mesh.vertices.size());
  EXPECT_TRUE(has_usable_uvs(atlas.mesh));
  // Cutting only duplicates: every triangle keeps its corners' positions.
  for (std::size_t t = 0; t < input.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(atlas.original_vertex[atlas.mesh.triangles[t][k]], input.triangles[t][k]);
      ASSERT_TRUE(atlas.mesh.vertices[atlas.mesh.triangles[t][k]] ==
                  input.vertices[input.triangles[t][k]]);
    }
  }
  // Every chart is a topological disk.
  std::vector<std::vector<int>> charts(static_cast<std::size_t>(atlas.chart_count));
  for (std::size_t t = 0; t < atlas.chart_of_triangle.size(); ++t)
    charts[atlas.chart_of_triangle[t]].push_back(static_cast<int>(t));
  for (const auto& chart : charts)
    EXPECT_TRUE(chart.size() == 1 || is_topological_disk(input, chart));
}

TEST(UvAtlas, icosphere_gets_an_lscm_atlas_within_the_distortion_bounds) {
  for (const int subdivisions : {2, 3, 4}) {
    const auto sphere = core::make_icosphere(0.04, subdivisions);
    // Its spherical UVs wrap around the seam: not usable for baking.
    EXPECT_FALSE(has_usable_uvs(sphere));
    const UvAtlas atlas = build_uv_atlas(sphere, {1024, 4});
    expect_valid_atlas(sphere, atlas);
    EXPECT_EQ(atlas.lscm_fallbacks, 0);
    expect_within_stated_bounds(measure_uv_distortion(atlas.mesh));
  }
}

TEST(UvAtlas, a_torus_is_cut_into_disks) {
  const auto mesh = torus(0.05, 0.015, 48, 24);
  const UvAtlas atlas = build_uv_atlas(mesh);
  expect_valid_atlas(mesh, atlas);
  expect_within_stated_bounds(measure_uv_distortion(atlas.mesh));
}

TEST(UvAtlas, charts_keep_their_gutter_apart) {
  const auto sphere = core::make_icosphere(0.04, 3);
  const int resolution = 256, gutter = 3;
  const UvAtlas atlas = build_uv_atlas(sphere, {resolution, gutter});
  // The bounding boxes of any two charts are at least two gutters apart, in texels.
  std::vector<int> chart_of_vertex(atlas.mesh.vertices.size());
  for (std::size_t t = 0; t < atlas.mesh.triangles.size(); ++t) {
    for (const int v : atlas.mesh.triangles[t])
      chart_of_vertex[v] = atlas.chart_of_triangle[t];
  }
  std::vector<core::Vec2> lo(atlas.chart_count, core::Vec2::Constant(2)),
      hi(atlas.chart_count, core::Vec2::Constant(-1));
  for (std::size_t v = 0; v < atlas.mesh.uvs.size(); ++v) {
    lo[chart_of_vertex[v]] = lo[chart_of_vertex[v]].cwiseMin(atlas.mesh.uvs[v]);
    hi[chart_of_vertex[v]] = hi[chart_of_vertex[v]].cwiseMax(atlas.mesh.uvs[v]);
  }
  for (int a = 0; a < atlas.chart_count; ++a) {
    for (int b = a + 1; b < atlas.chart_count; ++b) {
      const double gap_x = std::max(lo[b].x() - hi[a].x(), lo[a].x() - hi[b].x());
      const double gap_y = std::max(lo[b].y() - hi[a].y(), lo[a].y() - hi[b].y());
      EXPECT_GE(std::max(gap_x, gap_y) * resolution, 2.0 * gutter - 1e-6) << a << " " << b;
    }
  }
}

TEST(UvAtlas, keeps_vertex_attributes_and_normals_across_seams) {
  auto sphere = core::make_icosphere(0.03, 2);
  sphere.vertex_attributes["stiffness"] = std::vector<double>(sphere.vertices.size());
  for (std::size_t v = 0; v < sphere.vertices.size(); ++v)
    sphere.vertex_attributes["stiffness"][v] = static_cast<double>(v);
  const UvAtlas atlas = build_uv_atlas(sphere);
  ASSERT_EQ(atlas.mesh.normals.size(), atlas.mesh.vertices.size());
  for (std::size_t v = 0; v < atlas.mesh.vertices.size(); ++v) {
    EXPECT_EQ(atlas.mesh.vertex_attributes.at("stiffness")[v], atlas.original_vertex[v]);
    // Copies share the original's smooth normal, so seams do not show in lighting.
    EXPECT_GT(atlas.mesh.normals[v].dot(sphere.vertices[atlas.original_vertex[v]].normalized()),
              0.99);
  }
}

TEST(UvDistortion, an_isometric_map_scores_one_and_a_stretch_does_not) {
  core::SurfaceMesh square;
  square.vertices = {{0, 0, 0}, {0.02, 0, 0}, {0.02, 0.02, 0}, {0, 0.02, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  square.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  auto d = measure_uv_distortion(square);
  EXPECT_NEAR(d.l2_stretch, 1.0, 1e-12);
  EXPECT_NEAR(d.mean_conformal, 1.0, 1e-12);
  square.uvs = {{0, 0}, {1, 0}, {1, 0.25}, {0, 0.25}};
  d = measure_uv_distortion(square);
  EXPECT_GT(d.l2_stretch, 1.2);
  EXPECT_NEAR(d.mean_conformal, 4.0, 1e-9);
  square.uvs = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};  // mirrored: every triangle flips
  EXPECT_EQ(measure_uv_distortion(square).flipped, 2);
  EXPECT_FALSE(has_usable_uvs(square));
  EXPECT_THROW(build_uv_atlas(core::SurfaceMesh{}), core::InputError);
}

}  // namespace
}  // namespace viscera::textures
