#include "textures/surface_thumbnail.h"

#include <gtest/gtest.h>

#include <numbers>

#include "core/error.h"
#include "core/primitives/flat_primitive.h"
#include "core/primitives/icosphere.h"

namespace viscera::textures {
namespace {

bool is_background(const Image8& image, int x, int y) {
  const std::uint8_t* p = image.row(y) + 3 * x;
  return p[0] == 40 && p[1] == 44 && p[2] == 52;
}

TEST(SurfaceThumbnail, sphere_fills_its_disc_lit_at_the_centre_and_dark_at_the_rim) {
  const int size = 128;
  const Image8 image = render_surface_thumbnail(core::make_icosphere(0.03, 4), size);
  ASSERT_EQ(image.width, size);
  ASSERT_EQ(image.channels, 3);
  int covered = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      covered += !is_background(image, x, y);
  // The disc of radius 0.45 · size: π 0.45² of the pixels (the polyhedron is 0.1 % smaller).
  const double expected = std::numbers::pi * 0.45 * 0.45 * size * size;
  EXPECT_NEAR(covered, expected, 0.02 * expected);
  EXPECT_TRUE(is_background(image, 0, 0));
  EXPECT_TRUE(is_background(image, size - 1, size - 1));
  const std::uint8_t centre = image.row(size / 2)[3 * (size / 2)];
  const std::uint8_t rim = image.row(size / 2)[3 * (size / 2 + 56)];
  EXPECT_GE(centre, 215);  // facing the headlight: nearly the full tissue colour 222
  EXPECT_LT(rim, centre - 60);
  EXPECT_EQ(render_surface_thumbnail(core::make_icosphere(0.03, 4), size), image);
}

TEST(SurfaceThumbnail, open_sheet_is_drawn_from_either_side_and_bad_input_is_refused) {
  core::FlatPrimitive flat =
      core::make_flat(core::Vec3::Zero(), core::Vec3(0.05, 0, 0), core::Vec3(0, 0.05, 0), 3, 3);
  flat.open = true;
  core::SurfaceMesh sheet = core::tessellate_flat(flat);
  const Image8 front = render_surface_thumbnail(sheet, 64);
  for (auto& t : sheet.triangles)
    std::swap(t[1], t[2]);
  EXPECT_EQ(render_surface_thumbnail(sheet, 64), front);  // both sides shaded alike
  EXPECT_FALSE(is_background(front, 32, 32));
  EXPECT_THROW(render_surface_thumbnail(sheet, 8), core::UsageError);
  EXPECT_THROW(render_surface_thumbnail(core::SurfaceMesh{}, 64), core::UsageError);
}

TEST(SurfaceThumbnail, image_thumbnail_keeps_the_aspect_and_the_mean_colour) {
  Image8 image(300, 150, 3);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      std::uint8_t* p = image.row(y) + 3 * x;
      p[0] = x < 150 ? 200 : 0;  // left half red, right half blue
      p[2] = x < 150 ? 0 : 200;
    }
  const Image8 small = image_thumbnail(image, 100);
  ASSERT_EQ(small.width, 100);
  ASSERT_EQ(small.height, 50);
  EXPECT_EQ(small.row(25)[0], 200);           // left stays red
  EXPECT_EQ(small.row(25)[3 * 99 + 2], 200);  // right stays blue
  Image8 grey(40, 80, 1);
  const Image8 tall = image_thumbnail(grey, 32);
  EXPECT_EQ(tall.width, 16);
  EXPECT_EQ(tall.height, 32);
  EXPECT_EQ(tall.channels, 3);
  EXPECT_THROW(image_thumbnail(Image8{}, 32), core::UsageError);
}

TEST(SurfaceThumbnail, stress_strain_plot_draws_the_cubic_through_its_samples) {
  core::StressStrainCurve linear;
  linear.cubic = {0.0, 1000.0, 0.0, 0.0};  // a straight line: the plot's diagonal
  const Image8 line = render_stress_strain_thumbnail(linear, 100);
  // Margins of 10 px: (ε, σ) = (0.15, 150 Pa) is halfway, at column 50 and row 99 − 10 − 40.
  EXPECT_EQ(line.row(49)[3 * 50], 222);
  EXPECT_EQ(line.row(20)[3 * 50], 40);  // background above the line
  core::StressStrainCurve measured;
  measured.strain = {0.0, 0.1, 0.2};
  measured.stress = {0.0, 100.0, 800.0};
  measured.cubic = {0.0, 0.0, 0.0, 1.0e5};  // σ = 1e5 ε³: 100 Pa at 0.1, 800 Pa at 0.2
  const Image8 plot = render_stress_strain_thumbnail(measured, 100);
  EXPECT_EQ(plot.row(10)[3 * 90], 235);  // the last sample's dot at the top right corner
  EXPECT_EQ(render_stress_strain_thumbnail(measured, 100), plot);
  EXPECT_THROW(render_stress_strain_thumbnail(core::StressStrainCurve{}, 100), core::UsageError);
}

}  // namespace
}  // namespace viscera::textures
