// Segmentation on synthetic volumes whose answers are known exactly or analytically:
// core/segmentation/ threshold, region_growing, morphology, label_operations.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <numbers>

#include "core/error.h"
#include "core/segmentation/label_operations.h"
#include "core/segmentation/morphology.h"
#include "core/segmentation/region_growing.h"
#include "core/segmentation/threshold.h"

namespace viscera::core {
namespace {

/// An int16 volume of n³ voxels of 1 mm whose value at (i, j, k) is f(i, j, k).
ImageVolume volume_of(int n, const std::function<int(int, int, int)>& f) {
  ImageVolume v;
  v.dims = {n, n, n};
  v.spacing = Vec3::Constant(0.001);
  v.origin = Vec3(0.01, -0.02, 0.03);
  v.scalar_type = ScalarType::Int16;
  v.allocate();
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const auto value = static_cast<std::int16_t>(f(i, j, k));
        std::memcpy(v.voxels.data() + 2 * v.linear_index(i, j, k), &value, 2);
      }
  return v;
}

/// A label map of n³ voxels with `label` where inside(i, j, k).
LabelMap labels_of(int n, const std::function<int(int, int, int)>& label_at) {
  LabelMap labels = empty_label_map(volume_of(n, [](int, int, int) { return 0; }));
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        labels.set_label(labels.image.linear_index(i, j, k),
                         static_cast<std::uint16_t>(label_at(i, j, k)));
  return labels;
}

bool in_cube(int i, int j, int k, int lo, int hi) {
  return i >= lo && i < hi && j >= lo && j < hi && k >= lo && k < hi;
}

TEST(Threshold, a_ball_phantom_gives_the_ball_volume) {
  // Ball of radius 20 voxels (CT-like: 60 HU inside, -1000 outside).
  const double r = 20.0, c = 31.5;
  const auto ball = volume_of(
      64, [&](int i, int j, int k) { return std::hypot(i - c, j - c, k - c) <= r ? 60 : -1000; });
  const LabelMap labels = threshold(ball, 0, 100, 3);
  const double analytic = 4.0 / 3.0 * std::numbers::pi * r * r * r;  // 33510 voxels of 1 mm³
  const auto counts = label_counts(labels);
  ASSERT_EQ(counts.size(), 1u);
  EXPECT_NEAR(static_cast<double>(counts.at(3)), analytic, 0.01 * analytic);
  EXPECT_EQ(labels.image.origin, ball.origin);
  EXPECT_EQ(labels.image.spacing, ball.spacing);
  EXPECT_TRUE(label_counts(threshold(ball, 61, 100)).empty());
}

TEST(Threshold, multi_threshold_splits_shells_and_later_bands_win) {
  // Value = distance from the centre in voxels: shells [0,10] and (10,20].
  const auto distance = volume_of(48, [](int i, int j, int k) {
    return static_cast<int>(std::floor(std::hypot(i - 23.5, j - 23.5, k - 23.5)));
  });
  const auto labels = multi_threshold(distance, {{0, 9, 1}, {10, 19, 2}, {5, 9, 4}});
  const auto counts = label_counts(labels);
  const double inner = 4.0 / 3.0 * std::numbers::pi * 1000.0;  // radius 10
  const double outer = 4.0 / 3.0 * std::numbers::pi * 8000.0;  // radius 20
  const double core = 4.0 / 3.0 * std::numbers::pi * 125.0;    // radius 5
  // A ball of radius 5 voxels holds its analytic volume only to about 6 % on the lattice.
  EXPECT_NEAR(static_cast<double>(counts.at(1)), core, 0.08 * core);
  EXPECT_NEAR(static_cast<double>(counts.at(4)), inner - core, 0.03 * (inner - core));
  EXPECT_NEAR(static_cast<double>(counts.at(2)), outer - inner, 0.02 * (outer - inner));
}

TEST(Threshold, refuses_empty_windows_and_label_zero) {
  const auto v = volume_of(4, [](int, int, int) { return 0; });
  EXPECT_THROW(threshold(v, 5, 1), UsageError);
  EXPECT_THROW(threshold(v, std::nan(""), 1), UsageError);
  EXPECT_THROW(threshold(v, 0, 1, 0), UsageError);
}

TEST(RegionGrowing, stops_at_an_edge) {
  // Left half (i < 10) 100 ± 3 noise-free pattern, right half 200.
  const auto step =
      volume_of(20, [](int i, int j, int) { return i < 10 ? 100 + (i + j) % 4 : 200; });
  const auto labels = grow_region(step, {2, 5, 5}, 10.0, 7);
  EXPECT_EQ(label_counts(labels).at(7), 10u * 20 * 20);
  EXPECT_EQ(labels.label(step.linear_index(9, 0, 19)), 7);
  EXPECT_EQ(labels.label(step.linear_index(10, 5, 5)), 0);
}

TEST(RegionGrowing, takes_only_voxels_within_the_tolerance_of_the_seed) {
  // A ramp along x: seed value 10, tolerance 5 → x in [5, 15].
  const auto ramp = volume_of(24, [](int i, int, int) { return i; });
  EXPECT_EQ(label_counts(grow_region(ramp, {10, 3, 3}, 5.0)).at(1), 11u * 24 * 24);
  // A world point maps to the voxel whose centre is nearest.
  const Vec3 p = ramp.index_to_world(Vec3(10.4, 3.0, 2.6));
  EXPECT_EQ(voxel_at(ramp, p), (std::array<int, 3>{10, 3, 3}));
  EXPECT_THROW(voxel_at(ramp, ramp.origin - Vec3(0.01, 0, 0)), UsageError);
  EXPECT_THROW(grow_region(ramp, {24, 0, 0}, 1.0), UsageError);
}

TEST(RegionGrowing, does_not_cross_diagonal_contacts) {
  // Two cubes touching only along an edge are two regions under 6-connectivity.
  const auto v = volume_of(12, [](int i, int j, int k) {
    return (i < 5 && j < 5 && k < 8) || (i >= 5 && i < 10 && j >= 5 && j < 10 && k < 8) ? 1 : 0;
  });
  EXPECT_EQ(label_counts(grow_region(v, {0, 0, 0}, 0.0)).at(1), 5u * 5 * 8);
}

TEST(Morphology, opening_removes_a_speck_and_rounds_a_cube) {
  auto labels = labels_of(16, [](int i, int j, int k) { return in_cube(i, j, k, 2, 12) ? 1 : 0; });
  labels.set_label(labels.image.linear_index(14, 14, 14), 1);  // a 1-voxel speck
  const auto opened = open_labels(labels, 1);
  EXPECT_EQ(opened.label(labels.image.linear_index(14, 14, 14)), 0);
  // Erosion by the 6-neighbourhood leaves 8³; dilation restores faces, not the 12 edges of 8
  // voxels nor the 8 corners: 1000 − 96 − 8.
  EXPECT_EQ(label_counts(opened).at(1), 896u);
  EXPECT_THROW(open_labels(labels, 0), UsageError);
}

TEST(Morphology, closing_fills_a_hole_without_taking_other_labels) {
  auto labels = labels_of(16, [](int i, int j, int k) { return in_cube(i, j, k, 3, 13) ? 1 : 0; });
  labels.set_label(labels.image.linear_index(8, 8, 8), 0);  // a hole
  labels.set_label(labels.image.linear_index(8, 8, 9), 2);  // another tissue inside
  const auto closed = close_labels(labels, 1);
  EXPECT_EQ(closed.label(labels.image.linear_index(8, 8, 8)), 1);
  EXPECT_EQ(closed.label(labels.image.linear_index(8, 8, 9)), 2);
  EXPECT_EQ(label_counts(closed).at(1), 999u);
}

TEST(LabelOperations, keep_largest_component_per_label) {
  const auto labels = labels_of(20, [](int i, int j, int k) {
    if (in_cube(i, j, k, 0, 5)) return 1;                                 // 125 voxels
    if (i >= 5 && i < 8 && j >= 5 && j < 8 && k >= 5 && k < 8) return 1;  // 27, edge contact only
    if (in_cube(i, j, k, 12, 15)) return 2;                               // 27
    if (i == 18 && j == 18 && k == 18) return 2;                          // 1
    return 0;
  });
  const auto kept = keep_largest_component(labels);
  const auto counts = label_counts(kept);
  EXPECT_EQ(counts.at(1), 125u);
  EXPECT_EQ(counts.at(2), 27u);
}

TEST(LabelOperations, merge_remove_and_relabel_move_counts_and_names) {
  auto labels = labels_of(10, [](int i, int, int) {
    return i < 3 ? 1 : i < 6 ? 2 : i < 8 ? 3 : 0;
  });
  labels.names = {{1, "fat"}, {2, "muscle"}, {3, "myoma"}};
  const auto merged = merge_labels(labels, {1, 2}, 5);
  EXPECT_EQ(label_counts(merged), (std::map<std::uint16_t, std::size_t>{{3, 200}, {5, 600}}));
  EXPECT_EQ(merged.names.count(1), 0u);
  const auto removed = remove_label(labels, 2);
  EXPECT_EQ(label_counts(removed), (std::map<std::uint16_t, std::size_t>{{1, 300}, {3, 200}}));
  const auto renamed = relabel(labels, 3, 9);
  EXPECT_EQ(label_counts(renamed).at(9), 200u);
  EXPECT_EQ(renamed.names.at(9), "myoma");
  EXPECT_THROW(relabel(labels, 1, 2), UsageError);
}

}  // namespace
}  // namespace viscera::core
