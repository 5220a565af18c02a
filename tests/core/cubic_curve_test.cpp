#include "core/curves/cubic_curve.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"

namespace viscera::core {
namespace {

const std::vector<Vec3> kPoints = {{0, 0, 0},     {1, 0.2, 0},  {1.5, 1.5, 0.3},
                                   {3, 1.7, 0.1}, {3.2, 4, -1}, {2, 5, 0}};

/// Largest jump of the derivative with respect to the knot parameter across interior knots,
/// relative to its size.
double worst_derivative_jump(const CubicCurve& curve) {
  double worst = 0.0;
  const int interior = curve.closed() ? curve.segments() : curve.segments() - 1;
  for (int s = 1; s <= interior; ++s) {
    const double t = curve.knot(s % curve.segments() == 0 && curve.closed() ? 0 : s);
    const double eps = 1e-9 * curve.parameter_end();
    const Vec3 before = curve.derivative(t == 0.0 ? curve.parameter_end() - eps : t - eps);
    const Vec3 after = curve.derivative(t + eps);
    worst = std::max(worst, (before - after).norm() / after.norm());
  }
  return worst;
}

class CatmullRomCurve : public ::testing::TestWithParam<KnotSpacing> {};

TEST_P(CatmullRomCurve, interpolates_its_points_with_continuous_tangents_open_and_closed) {
  for (const bool closed : {false, true}) {
    const CubicCurve curve = catmull_rom_curve(kPoints, GetParam(), closed);
    ASSERT_EQ(curve.segments(), closed ? 6 : 5);
    for (int s = 0; s < curve.segments(); ++s) {
      EXPECT_LT((curve.point(curve.knot(s)) - kPoints[static_cast<std::size_t>(s)]).norm(), 1e-14);
    }
    if (!closed) {
      EXPECT_LT((curve.point(curve.parameter_end()) - kPoints.back()).norm(), 1e-14);
    }
    // C1 in the knot parameter: the Bézier handles are scaled by the knot gaps.
    EXPECT_LT(worst_derivative_jump(curve), 1e-6) << "closed " << closed;
  }
}

TEST_P(CatmullRomCurve, matches_the_existing_spline_segment_by_segment) {
  for (const bool closed : {false, true}) {
    const CubicCurve curve = catmull_rom_curve(kPoints, GetParam(), closed);
    const CatmullRomSpline spline(kPoints, GetParam(), closed);
    for (int s = 0; s < curve.segments(); ++s) {
      const auto a = curve.bezier(s), b = spline.bezier(s);
      for (int k = 0; k < 4; ++k)
        EXPECT_LT((a[static_cast<std::size_t>(k)] - b[static_cast<std::size_t>(k)]).norm(), 1e-12);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Spacings, CatmullRomCurve,
                         ::testing::Values(KnotSpacing::Uniform, KnotSpacing::Centripetal,
                                           KnotSpacing::ChordLength));

TEST(CatmullRomCurve,
     chord_length_knots_of_collinear_uneven_points_give_a_straight_line_at_unit_speed) {
  const std::vector<Vec3> points = {{0, 0, 0}, {0.1, 0, 0}, {0.5, 0, 0}, {0.6, 0, 0}, {2, 0, 0}};
  const CubicCurve curve = catmull_rom_curve(points, KnotSpacing::ChordLength, false);
  EXPECT_DOUBLE_EQ(curve.parameter_end(), 2.0);
  for (int k = 0; k <= 100; ++k) {
    const double t = 0.02 * k;
    EXPECT_NEAR(curve.point(t).x(), t, 1e-12);
    EXPECT_NEAR(curve.derivative(t).x(), 1.0, 1e-12);
  }
}

TEST(CubicBspline, is_twice_continuously_differentiable_and_clamps_its_ends) {
  const CubicCurve curve = cubic_bspline_curve(kPoints, false);
  EXPECT_LT((curve.point(0.0) - kPoints.front()).norm(), 1e-14);
  EXPECT_LT((curve.point(curve.parameter_end()) - kPoints.back()).norm(), 1e-14);
  for (int s = 1; s < curve.segments(); ++s) {
    const double t = curve.knot(s);
    EXPECT_LT((curve.derivative(t - 1e-12) - curve.derivative(t + 1e-12)).norm(), 1e-9);
    EXPECT_LT((curve.second_derivative(t - 1e-12) - curve.second_derivative(t + 1e-12)).norm(),
              1e-8);
  }
  // A closed B-spline of a square's corners is symmetric: its points lie inside the square.
  const CubicCurve loop =
      cubic_bspline_curve({{1, 1, 0}, {-1, 1, 0}, {-1, -1, 0}, {1, -1, 0}}, true);
  EXPECT_EQ(loop.segments(), 4);
  EXPECT_LT((loop.point(0.0) - Vec3(2.0 / 3.0, 2.0 / 3.0, 0.0)).norm(),
            1e-14);  // (P3 + 4 P0 + P1) / 6
  EXPECT_LT((loop.point(0.0) - loop.point(4.0)).norm(), 1e-14);
}

TEST(HermiteCurve, reproduces_a_cubic_polynomial_from_its_values_and_derivatives) {
  const auto f = [](double t) { return Vec3(t, t * t, t * t * t - 2.0 * t); };
  const auto df = [](double t) { return Vec3(1.0, 2.0 * t, 3.0 * t * t - 2.0); };
  const std::vector<double> knots = {0.0, 0.5, 1.7, 2.0};
  std::vector<Vec3> points, tangents;
  for (const double t : knots) {
    points.push_back(f(t));
    tangents.push_back(df(t));
  }
  const CubicCurve curve = hermite_curve(points, tangents, {0.5, 1.2, 0.3}, false);
  for (int k = 0; k <= 40; ++k) {
    const double t = 0.05 * k;
    EXPECT_LT((curve.point(t) - f(t)).norm(), 1e-12) << t;
    EXPECT_LT((curve.derivative(t) - df(t)).norm(), 1e-11) << t;
  }
  EXPECT_THROW(hermite_curve(points, {tangents[0]}, {}, false), UsageError);
}

TEST(CubicCurve, rejects_bad_nets_and_coinciding_points) {
  EXPECT_THROW(CubicCurve({Vec3::Zero(), Vec3::UnitX()}, {1.0}, false), UsageError);
  EXPECT_THROW(
      catmull_rom_curve({{0, 0, 0}, {0, 0, 0}, {1, 0, 0}}, KnotSpacing::ChordLength, false),
      UsageError);
  EXPECT_THROW(cubic_bspline_curve({{0, 0, 0}, {1, 0, 0}}, true), UsageError);
}

}  // namespace
}  // namespace viscera::core
