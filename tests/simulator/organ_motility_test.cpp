#include "simulator/physics/organ_motility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"

namespace viscera::sim {
namespace {

/// Knots on a cylinder of radius 1 cm and length 10 cm along x: a bowel segment.
std::vector<core::Vec3> cylinder_knots() {
  std::vector<core::Vec3> knots;
  for (int ring = 0; ring <= 20; ++ring) {
    for (int k = 0; k < 12; ++k) {
      const double angle = 2.0 * std::numbers::pi * k / 12.0;
      knots.emplace_back(-0.05 + 0.005 * ring, 0.01 * std::cos(angle), 0.01 * std::sin(angle));
    }
  }
  return knots;
}

core::MotilitySpec regular_wave() {
  core::MotilitySpec spec;
  spec.amplitude_mean = 0.002;
  spec.wave_speed = 0.02;
  spec.wave_direction = core::Vec3::UnitX();
  spec.frequency = 0.5;
  return spec;
}

TEST(OrganMotility, FindsTheAxisAndMovesRingsRadiallyAndAlongIt) {
  const OrganMotility motility(regular_wave(), cylinder_knots(), 1);
  EXPECT_NEAR(std::abs(motility.axis().x()), 1.0, 1e-12);
  EXPECT_NEAR(motility.centroid().norm(), 0.0, 1e-12);
  // Knot 3 of ring 10 (x = 0) sits at 90°, on +z: its radial direction is +z.
  const std::size_t i = 10 * 12 + 3;
  for (const double t : {0.0, 0.3, 0.7, 1.1}) {
    const core::Vec3 d = motility.displacement(i, t);
    const double phase = 2.0 * std::numbers::pi * 0.5 * t;  // x = 0: no delay
    EXPECT_NEAR(d.z(), 0.002 * std::sin(phase), 1e-12) << t;
    EXPECT_NEAR(d.x(), 0.001 * std::cos(phase), 1e-12) << t;
    EXPECT_NEAR(d.y(), 0.0, 1e-12) << t;
  }
}

TEST(OrganMotility, IsAWaveTravellingAtItsSpeed) {
  const OrganMotility motility(regular_wave(), cylinder_knots(), 1);
  // Ring 14 lies 2 cm downstream of ring 10: it moves as ring 10 did 1 s earlier.
  for (const double t : {1.0, 1.25, 2.5}) {
    const core::Vec3 upstream = motility.displacement(10 * 12 + 5, t - 0.02 / 0.02);
    const core::Vec3 downstream = motility.displacement(14 * 12 + 5, t);
    EXPECT_NEAR((upstream - downstream).norm(), 0.0, 1e-12) << t;
  }
  // The same inputs give the same positions; another seed changes only drawn parts (none here).
  EXPECT_EQ(motility.positions(0.4),
            OrganMotility(regular_wave(), cylinder_knots(), 2).positions(0.4));
}

TEST(OrganMotility, DrawsAmplitudesAndFrequenciesWithinTheirSpread) {
  core::MotilitySpec spec = regular_wave();
  spec.amplitude_variance = 1e-6;  // ±1 mm
  spec.frequency_disturbance = 0.2;
  const auto knots = cylinder_knots();
  const OrganMotility motility(spec, knots, 7);
  double largest = 0.0;
  for (std::size_t i = 0; i < knots.size(); ++i) {
    for (double t = 0.0; t < 4.0; t += 0.05)
      largest = std::max(largest, motility.displacement(i, t).norm());
  }
  // |d| ≤ A √(1 + ¼) with A ≤ 3 mm; the drawn spread shows above the mean's bound.
  EXPECT_LE(largest, 0.003 * std::sqrt(1.25) + 1e-12);
  EXPECT_GT(largest, 0.002 * std::sqrt(1.25) * 1.05);
  EXPECT_NE(motility.positions(1.3), OrganMotility(spec, knots, 8).positions(1.3));
}

TEST(OrganMotility, ContractsOncePerInterval) {
  core::MotilitySpec spec = regular_wave();
  spec.amplitude_mean = 0.002;
  spec.contraction_interval_mean = 2.0;
  spec.contraction_interval_variance = 0.04;  // ±0.2 s
  const OrganMotility motility(spec, cylinder_knots(), 3);
  EXPECT_EQ(motility.contraction(0.5), 0.0);
  // Between 1.8 s and 2.2 s + τ the first contraction peaks at 1.
  double peak = 0.0;
  for (double t = 1.7; t < 2.6; t += 0.001)
    peak = std::max(peak, motility.contraction(t));
  EXPECT_NEAR(peak, 1.0, 1e-3);
  EXPECT_LT(motility.contraction(3.7), 0.05);  // gone before the next one
  spec.contraction_interval_mean = 0.0;
  EXPECT_EQ(OrganMotility(spec, cylinder_knots(), 3).contraction(2.15), 0.0);
}

TEST(OrganMotility, RefusesUnusableSpecs) {
  core::MotilitySpec spec = regular_wave();
  spec.wave_speed = 0.0;
  EXPECT_THROW(OrganMotility(spec, cylinder_knots(), 1), core::UsageError);
  EXPECT_THROW(OrganMotility(regular_wave(), {}, 1), core::UsageError);
}

}  // namespace
}  // namespace viscera::sim
