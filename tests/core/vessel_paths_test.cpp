#include "core/scenario/vessel_paths.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"

namespace viscera::core {
namespace {

/// A 4 cm trunk along x (radius 2 mm) and a thin 2 cm branch (radius 0.5 mm) leaving its distal
/// end along y, in m.
VesselTree trunk_and_branch() {
  VesselTree tree;
  tree.id = "uterine";
  VesselSegment trunk;
  trunk.proximal = Vec3::Zero();
  trunk.distal = Vec3(0.04, 0.0, 0.0);
  trunk.radius = 0.002;
  VesselSegment branch;
  branch.id = 1;
  branch.parent = 0;
  branch.proximal = trunk.distal;
  branch.distal = Vec3(0.04, 0.02, 0.0);
  branch.radius = 0.0005;
  tree.segments = {trunk, branch};
  return tree;
}

TEST(VesselPaths, root_paths_run_from_the_top_of_the_hierarchy_to_each_segment) {
  const VesselTree tree = trunk_and_branch();
  EXPECT_EQ(vessel_root_paths(tree), (std::vector<std::vector<int>>{{0}, {0, 1}}));
  EXPECT_EQ(vessel_child_counts(tree), (std::vector<int>{1, 0}));
}

TEST(VesselPaths, nearest_point_on_a_segment_is_the_foot_on_its_axis_clamped_to_its_ends) {
  const VesselTree tree = trunk_and_branch();
  // 3 mm beside the trunk, a quarter of the way along.
  const VesselSegmentPoint beside = nearest_point_on_segment(tree, 0, Vec3(0.01, 0.003, 0.0));
  EXPECT_EQ(beside.segment, 0);
  EXPECT_NEAR(beside.along, 0.25, 1e-12);
  EXPECT_NEAR(beside.projection, 0.25, 1e-12);
  EXPECT_TRUE(beside.point.isApprox(Vec3(0.01, 0.0, 0.0), 1e-12));
  EXPECT_NEAR(beside.distance, 0.003, 1e-12);
  EXPECT_NEAR(beside.wall_distance, 0.001, 1e-12);
  // 1 cm behind the proximal end: the end is nearest, the foot lies a quarter before it.
  const VesselSegmentPoint behind = nearest_point_on_segment(tree, 0, Vec3(-0.01, 0.0, 0.0));
  EXPECT_EQ(behind.along, 0.0);
  EXPECT_NEAR(behind.projection, -0.25, 1e-12);
  EXPECT_EQ(behind.point, Vec3::Zero());
  EXPECT_NEAR(behind.distance, 0.01, 1e-12);
  // Inside the lumen the wall distance is negative.
  EXPECT_LT(nearest_point_on_segment(tree, 0, Vec3(0.02, 0.001, 0.0)).wall_distance, 0.0);
  EXPECT_THROW(nearest_point_on_segment(tree, 2, Vec3::Zero()), UsageError);
}

TEST(VesselPaths, a_segment_of_zero_length_answers_with_its_proximal_end) {
  VesselTree tree = trunk_and_branch();
  tree.segments[1].distal = tree.segments[1].proximal;
  const VesselSegmentPoint at = nearest_point_on_segment(tree, 1, Vec3(0.04, 0.0, 0.003));
  EXPECT_EQ(at.along, 0.0);
  EXPECT_EQ(at.projection, 0.0);
  EXPECT_EQ(at.point, Vec3(0.04, 0.0, 0.0));
  EXPECT_NEAR(at.distance, 0.003, 1e-12);
}

TEST(VesselPaths, nearest_point_on_a_vessel_is_on_the_segment_whose_wall_lies_nearest) {
  const VesselTree tree = trunk_and_branch();
  // 2.5 mm from the branch's axis but 3 mm from the trunk's: the trunk's thick wall is nearer.
  const Vec3 p(0.0375, 0.003, 0.0);
  const VesselSegmentPoint near_trunk = nearest_point_on_vessel(tree, p);
  EXPECT_EQ(near_trunk.segment, 0);
  EXPECT_NEAR(near_trunk.wall_distance, 0.001, 1e-12);
  // Beside the branch, well past the trunk's end.
  const VesselSegmentPoint near_branch = nearest_point_on_vessel(tree, Vec3(0.041, 0.015, 0.0));
  EXPECT_EQ(near_branch.segment, 1);
  EXPECT_NEAR(near_branch.along, 0.75, 1e-12);
  EXPECT_NEAR(near_branch.wall_distance, 0.0005, 1e-12);
  // No segments, no nearest point.
  const VesselSegmentPoint none = nearest_point_on_vessel(VesselTree{}, p);
  EXPECT_EQ(none.segment, -1);
  EXPECT_TRUE(std::isinf(none.wall_distance));
}

}  // namespace
}  // namespace viscera::core
