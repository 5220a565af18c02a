#include "core/curves/rotation_minimizing_frames.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/curves/arc_length.h"

namespace viscera::core {
namespace {

std::vector<Vec3> helix_points(int n, double radius, double pitch) {
  std::vector<Vec3> points;
  for (int i = 0; i <= n; ++i) {
    const double a = 4.0 * std::numbers::pi * i / n;
    points.emplace_back(radius * std::cos(a), radius * std::sin(a),
                        pitch * a / (2.0 * std::numbers::pi));
  }
  return points;
}

TEST(RotationMinimizingFrames, stay_orthonormal_and_do_not_twist_about_the_tangent) {
  const CubicCurve curve =
      catmull_rom_curve(helix_points(12, 0.01, 0.006), KnotSpacing::ChordLength, false);
  const ArcLengthTable table(curve);
  const int n = 4000;
  const auto parameters = even_arc_length_parameters(table, n);
  const auto frames = rotation_minimizing_frames(curve, parameters, Vec3::UnitZ());
  const double ds = table.length() / n;
  double mean_twist = 0.0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const auto& f = frames[i];
    EXPECT_NEAR(f.tangent.norm(), 1.0, 1e-12);
    EXPECT_NEAR(f.normal.norm(), 1.0, 1e-12);
    EXPECT_NEAR(f.tangent.dot(f.normal), 0.0, 1e-12);
    EXPECT_LT((f.binormal - f.tangent.cross(f.normal)).norm(), 1e-12);
    if (i + 1 < frames.size()) {
      // The angular velocity of an RMF has no component along the tangent: dN/ds · B = 0
      // (up to the discretisation, largest where the curvature jumps at the knots).
      const Vec3 dn = (frames[i + 1].normal - f.normal) / ds;
      mean_twist += std::abs(dn.dot(0.5 * (f.binormal + frames[i + 1].binormal))) / n;
    }
  }
  // For comparison, the Frenet frame of the helix turns about its tangent at the torsion
  // c / (r² + c²) with c = pitch / 2π.
  const double c = 0.006 / (2.0 * std::numbers::pi);
  const double torsion = c / (0.01 * 0.01 + c * c);
  EXPECT_LT(mean_twist, 1e-3 * torsion);
  // Ten times fewer frames land on nearly the same last normal (the method is fourth order).
  std::vector<double> coarse;
  for (std::size_t i = 0; i < parameters.size(); i += 10)
    coarse.push_back(parameters[i]);
  const auto coarse_frames = rotation_minimizing_frames(curve, coarse, Vec3::UnitZ());
  EXPECT_LT((coarse_frames.back().normal - frames.back().normal).norm(), 1e-4);
}

TEST(RotationMinimizingFrames, keep_the_plane_normal_on_a_planar_curve_and_close_a_loop) {
  const CubicCurve open = catmull_rom_curve({{0, 0, 0}, {1, 0.5, 0}, {2, -0.3, 0}, {3, 1, 0}},
                                            KnotSpacing::ChordLength, false);
  std::vector<double> parameters;
  for (int k = 0; k <= 50; ++k)
    parameters.push_back(open.parameter_end() * k / 50);
  for (const auto& f : rotation_minimizing_frames(open, parameters, Vec3::UnitZ())) {
    EXPECT_LT((f.normal - Vec3::UnitZ()).norm(), 1e-12);
  }
  // A closed, non-planar loop: frames transported around do not come back aligned by
  // themselves; close_loop spreads the difference so the last frame equals the first.
  std::vector<Vec3> saddle;
  for (int i = 0; i < 12; ++i) {
    const double a = 2.0 * std::numbers::pi * i / 12;
    saddle.emplace_back(std::cos(a), std::sin(a), 0.4 * std::cos(2.0 * a));
  }
  const CubicCurve loop = catmull_rom_curve(saddle, KnotSpacing::ChordLength, true);
  parameters.clear();
  for (int k = 0; k <= 240; ++k)
    parameters.push_back(loop.parameter_end() * k / 240);
  const auto frames = rotation_minimizing_frames(loop, parameters, Vec3::UnitZ(), true);
  EXPECT_LT((frames.back().normal - frames.front().normal).norm(), 1e-9);
}

}  // namespace
}  // namespace viscera::core
