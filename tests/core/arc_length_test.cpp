#include "core/curves/arc_length.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace viscera::core {
namespace {

std::vector<Vec3> circle_points(int n, double radius) {
  std::vector<Vec3> points;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    points.emplace_back(radius * std::cos(a), radius * std::sin(a), 0.0);
  }
  return points;
}

std::vector<Vec3> helix_points(int n, double radius, double pitch) {
  std::vector<Vec3> points;
  for (int i = 0; i <= n; ++i) {
    const double a = 4.0 * std::numbers::pi * i / n;
    points.emplace_back(radius * std::cos(a), radius * std::sin(a),
                        pitch * a / (2.0 * std::numbers::pi));
  }
  return points;
}

TEST(ArcLength, straight_uneven_catmull_rom_has_its_exact_length_and_inverse) {
  const ArcLengthTable table(catmull_rom_curve({{0, 0, 0}, {0.3, 0.4, 0}, {0.6, 0.8, 0}, {3, 4, 0}},
                                               KnotSpacing::ChordLength, false));
  EXPECT_NEAR(table.length(), 5.0, 1e-12);
  for (const double s : {0.0, 0.25, 1.0, 2.5, 4.99, 5.0}) {
    const double t = table.parameter_at(s);
    EXPECT_NEAR(table.length_at(t), s, 1e-10);
    EXPECT_NEAR(table.curve().point(t).norm(), s, 1e-9);  // the line starts at the origin
  }
}

TEST(ArcLength, closed_chord_length_circle_length_converges_to_two_pi_r) {
  double previous = 1.0;
  for (const int n : {8, 16, 32, 64}) {
    const ArcLengthTable table(
        catmull_rom_curve(circle_points(n, 0.02), KnotSpacing::ChordLength, true));
    const double error = std::abs(table.length() / (2.0 * std::numbers::pi * 0.02) - 1.0);
    EXPECT_LT(error, previous / 4.0) << n;  // at least second order
    previous = error;
  }
  EXPECT_LT(previous, 2e-6);
}

TEST(ArcLength, even_parameters_give_equal_arc_steps) {
  const ArcLengthTable table(
      catmull_rom_curve(helix_points(9, 0.01, 0.004), KnotSpacing::Centripetal, false));
  const auto parameters = even_arc_length_parameters(table, 37);
  ASSERT_EQ(parameters.size(), 38u);
  for (std::size_t i = 0; i + 1 < parameters.size(); ++i) {
    EXPECT_NEAR(table.length_at(parameters[i + 1]) - table.length_at(parameters[i]),
                table.length() / 37.0, 1e-10);
  }
}

}  // namespace
}  // namespace viscera::core
