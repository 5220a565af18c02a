#include "core/curves/catmull_rom.h"

#include <gtest/gtest.h>

#include <numbers>

#include "core/error.h"

namespace viscera::core {
namespace {

class CatmullRom : public ::testing::TestWithParam<KnotSpacing> {};

TEST_P(CatmullRom, interpolates_its_points_with_continuous_tangents) {
  const std::vector<Vec3> points = {
      {0, 0, 0}, {1, 0.2, 0}, {1.5, 1.5, 0.3}, {3, 1.7, 0.1}, {3.2, 4, -1}};
  for (const bool closed : {false, true}) {
    const CatmullRomSpline spline(points, GetParam(), closed);
    for (int s = 0; s < spline.segments(); ++s) {
      EXPECT_TRUE(spline.evaluate(s, 0.0).isApprox(points[static_cast<std::size_t>(s)], 1e-15));
      EXPECT_TRUE(spline.evaluate(s, 1.0).isApprox(
          points[static_cast<std::size_t>((s + 1) % points.size())], 1e-15));
      if (s + 1 < spline.segments()) {
        // Same direction on both sides of a joint; with knot-scaled Bézier handles the
        // derivatives with respect to the global knot parameter match too.
        const Vec3 out = spline.derivative(s, 1.0).normalized();
        const Vec3 in = spline.derivative(s + 1, 0.0).normalized();
        EXPECT_GT(out.dot(in), 1.0 - 1e-12) << s;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Spacings, CatmullRom,
                         ::testing::Values(KnotSpacing::Uniform, KnotSpacing::Centripetal,
                                           KnotSpacing::ChordLength));

TEST(CatmullRomSpline, closed_chord_length_curve_through_a_circle_stays_near_it) {
  std::vector<Vec3> points;
  const int n = 8;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    points.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
  const CatmullRomSpline spline(points, KnotSpacing::ChordLength, true);
  double worst = 0.0;
  for (int s = 0; s < spline.segments(); ++s)
    for (int k = 0; k <= 10; ++k)
      worst = std::max(worst, std::abs(spline.evaluate(s, k / 10.0).norm() - 1.0));
  EXPECT_LT(worst, 0.01);  // eight points already give a circle to within 1 %
  EXPECT_THROW(CatmullRomSpline({{0, 0, 0}, {0, 0, 0}}, KnotSpacing::ChordLength, false),
               UsageError);
}

}  // namespace
}  // namespace viscera::core
