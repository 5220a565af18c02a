// Vessel trees: CCO growth in surface and label-map organs, L-system and spline trees, their
// physiology (Murray's law, flow conservation), geometry (no touching walls, inside the organ),
// determinism, JSON, and closed pipe meshes.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "core/primitives/icosphere.h"
#include "templates/vessels/cco_vessel_generator.h"
#include "templates/vessels/lsystem_vessel_tree.h"
#include "templates/vessels/spline_vessel_tree.h"
#include "templates/vessels/vessel_pipe_mesh.h"
#include "templates/vessels/vessel_tree_analysis.h"
#include "templates/vessels/vessel_tree_json.h"

namespace viscera::templates {
namespace {

using core::Vec3;

/// Asserts every check of validate_vessel_tree, Murray's law within 1 %, and no touching walls.
void expect_physiological(const core::VesselTree& tree) {
  for (const auto& issue : validate_vessel_tree(tree, 0.01)) {
    ADD_FAILURE() << tree.id << issue.json_pointer << ": " << issue.message;
  }
  EXPECT_LT(murray_deviation(tree), 0.01);
  EXPECT_TRUE(find_intersections(tree).empty());
}

/// An ellipsoidal organ as a label map: 48×36×28 voxels of 1 mm, label 3 inside.
core::LabelMap ellipsoid_labels() {
  core::LabelMap labels;
  labels.image.dims = {48, 36, 28};
  labels.image.spacing = Vec3::Constant(1e-3);
  labels.image.origin = Vec3(0.01, -0.02, 0.0);
  labels.image.scalar_type = core::ScalarType::UInt16;
  labels.image.allocate();
  labels.names[3] = "uterus";
  for (int k = 0; k < 28; ++k)
    for (int j = 0; j < 36; ++j)
      for (int i = 0; i < 48; ++i) {
        const double x = (i - 23.5) / 23.0, y = (j - 17.5) / 17.0, z = (k - 13.5) / 13.0;
        if (x * x + y * y + z * z <= 1.0) labels.set_label(labels.image.linear_index(i, j, k), 3);
      }
  return labels;
}

TEST(CcoVesselTree, grows_a_physiological_tree_inside_a_ball) {
  const SurfaceMeshDomain ball(core::make_icosphere(0.04, 3));
  CcoOptions options;
  options.terminals = 300;
  options.seed = 11;
  const auto tree = grow_cco_tree(ball, options);
  EXPECT_EQ(terminal_count(tree), 300);
  EXPECT_EQ(tree.segments.size(), 599u);
  expect_physiological(tree);
  EXPECT_NEAR(tree.segments[0].flow, options.perfusion_flow, 1e-9 * options.perfusion_flow);
  for (const auto& s : tree.segments) {
    ASSERT_TRUE(ball.contains_segment(s.proximal, s.distal)) << s.id;
  }
  // Poiseuille: the pressure drop along every root-to-terminal path is the prescribed one.
  const auto children = segment_children(tree);
  std::vector<double> drop(tree.segments.size(), 0.0);
  for (std::size_t i = 0; i < tree.segments.size(); ++i) {
    const auto& s = tree.segments[i];
    const double resistance =
        8.0 * options.viscosity * segment_length(s) / (std::numbers::pi * std::pow(s.radius, 4));
    drop[i] = (s.parent >= 0 ? drop[s.parent] : 0.0) + resistance * s.flow;
    if (children[i].empty()) {
      EXPECT_NEAR(drop[i], options.perfusion_pressure - options.terminal_pressure, 1.0) << i;
    }
  }
}

TEST(CcoVesselTree, same_seed_same_tree_and_seeds_differ) {
  const SurfaceMeshDomain ball(core::make_icosphere(0.03, 2));
  CcoOptions options;
  options.terminals = 60;
  options.seed = 4;
  const auto a = grow_cco_tree(ball, options);
  EXPECT_EQ(a, grow_cco_tree(ball, options));
  options.seed = 5;
  EXPECT_NE(a, grow_cco_tree(ball, options));
}

TEST(CcoVesselTree, grows_inside_a_label_map) {
  const LabelMapDomain organ(ellipsoid_labels(), 3);
  CcoOptions options;
  options.terminals = 150;
  const auto tree = grow_cco_tree(organ, options);
  EXPECT_EQ(terminal_count(tree), 150);
  expect_physiological(tree);
  for (const auto& s : tree.segments)
    ASSERT_TRUE(organ.contains(s.distal)) << s.id;
}

TEST(CcoVesselTree, reaches_given_perfusion_points) {
  const SurfaceMeshDomain ball(core::make_icosphere(0.04, 3));
  CcoOptions options;
  core::Rng rng(8);
  for (int i = 0; i < 40; ++i)
    options.perfusion_points.push_back(ball.random_point(rng));
  const auto tree = grow_cco_tree(ball, options);
  expect_physiological(tree);
  const auto children = segment_children(tree);
  for (const auto& p : options.perfusion_points) {
    bool reached = false;
    for (std::size_t i = 0; i < children.size(); ++i) {
      reached |= children[i].empty() && (tree.segments[i].distal - p).norm() < 1e-12;
    }
    EXPECT_TRUE(reached) << p.transpose();
  }
}

TEST(CcoVesselTree, empty_domains_and_bad_options_are_refused) {
  core::LabelMap empty = ellipsoid_labels();
  EXPECT_THROW(LabelMapDomain(empty, 7), core::InputError);
  EXPECT_THROW(SurfaceMeshDomain(core::SurfaceMesh{}), core::InputError);
  const SurfaceMeshDomain ball(core::make_icosphere(0.03, 2));
  CcoOptions options;
  options.terminals = 0;
  EXPECT_THROW(grow_cco_tree(ball, options), core::UsageError);
  options.terminals = 10;
  options.inlet = Vec3(1, 1, 1);
  EXPECT_THROW(grow_cco_tree(ball, options), core::UsageError);
}

TEST(LsystemVesselTree, radii_follow_murray_and_branches_never_touch) {
  for (const std::uint64_t seed : {1ULL, 2ULL, 3ULL}) {
    LsystemVesselOptions options;
    options.generations = 7;
    options.seed = seed;
    options.turtle.step = 0.012;
    options.turtle.angle_jitter = 8.0;
    options.turtle.seed = seed;
    const auto tree = lsystem_vessel_tree(core::Lsystem::parse(kDefaultVesselGrammar), options);
    EXPECT_GT(terminal_count(tree), 16) << seed;
    expect_physiological(tree);
    EXPECT_NEAR(tree.segments[0].radius, options.root_radius, 1e-15);
  }
}

TEST(LsystemVesselTree, grammar_widths_split_the_flow) {
  LsystemVesselOptions options;
  options.turtle.angle = 40.0;
  // One bifurcation with daughter widths 0.9 and 0.5: flows split 0.729 : 0.125.
  const auto tree =
      lsystem_vessel_tree(core::Lsystem::parse("axiom: F(1,1)[+F(1,0.9)][-F(1,0.5)]\n"), options);
  ASSERT_EQ(tree.segments.size(), 3u);
  EXPECT_NEAR(tree.segments[1].flow / tree.segments[2].flow, 0.729 / 0.125, 1e-9);
  expect_physiological(tree);
}

TEST(LsystemVesselTree, clips_to_the_domain) {
  const SurfaceMeshDomain ball(core::make_icosphere(0.02, 2));
  LsystemVesselOptions options;
  options.domain = &ball;
  options.turtle.origin = Vec3(0, -0.015, 0);
  options.turtle.step = 0.02;  // long enough to leave the ball
  const auto tree = lsystem_vessel_tree(core::Lsystem::parse(kDefaultVesselGrammar), options);
  for (const auto& s : tree.segments)
    EXPECT_TRUE(ball.contains(s.distal));
  expect_physiological(tree);
}

TEST(SplineVesselTree, branches_attach_to_their_parent_and_obey_murray) {
  std::vector<SplineVesselBranch> branches(3);
  branches[0].control_points = {{0, 0, 0}, {0, 0.02, 0.002}, {0.002, 0.04, 0.0}, {0, 0.06, 0}};
  branches[1].control_points = {{0, 0, 0}, {0.015, 0.035, 0}, {0.03, 0.05, 0.004}};
  branches[1].parent_branch = 0;
  branches[1].attach = 0.4;
  branches[2].control_points = {{0, 0, 0}, {-0.02, 0.05, 0}, {-0.03, 0.07, 0}};
  branches[2].parent_branch = 0;
  branches[2].attach = 0.75;
  branches[2].flow_weight = 0.5;
  SplineVesselOptions options;
  options.sample_spacing = 0.004;
  const auto tree = spline_vessel_tree(branches, options);
  expect_physiological(tree);
  EXPECT_EQ(terminal_count(tree), 3);
  // The curve passes through its control points.
  for (const auto& p : branches[0].control_points) {
    bool on_curve = false;
    for (const auto& s : tree.segments)
      on_curve |= (s.proximal - p).norm() < 1e-12 || (s.distal - p).norm() < 1e-12;
    EXPECT_TRUE(on_curve) << p.transpose();
  }
  EXPECT_THROW(spline_vessel_tree({SplineVesselBranch{{{0, 0, 0}}, -1, 1.0, 1.0}}, options),
               core::UsageError);
}

TEST(SplineVesselTree, reads_branches_from_json_with_pointers) {
  const auto json = nlohmann::json::parse(R"({"branches": [{"points": [[0,0,0],[0,0.01,0]]},
      {"points": [[0,0,0],[0.01,0.02,0]], "parent": 0, "attach": 0.5, "flow_weight": 2}]})");
  const auto branches = spline_branches_from_json(json);
  ASSERT_EQ(branches.size(), 2u);
  EXPECT_EQ(branches[1].parent_branch, 0);
  EXPECT_DOUBLE_EQ(branches[1].flow_weight, 2.0);
  try {
    spline_branches_from_json(nlohmann::json::parse(R"({"branches": [{"points": [[0,0]]}]})"));
    FAIL();
  } catch (const core::ValidationError& e) {
    EXPECT_EQ(e.location().json_pointer, "/branches/0/points/0");
  }
}

TEST(VesselTreeJson, round_trips_and_carries_derived_members) {
  const SurfaceMeshDomain ball(core::make_icosphere(0.03, 2));
  CcoOptions options;
  options.terminals = 30;
  const auto tree = grow_cco_tree(ball, options);
  const auto json = vessel_tree_to_json(tree);
  EXPECT_EQ(json["summary"]["terminals"], 30);
  EXPECT_EQ(json["summary"]["intersections"], 0);
  EXPECT_EQ(json["tree"]["segments"][0]["children"].size(), 2u);
  const auto back = vessel_tree_from_json(nlohmann::json::parse(json.dump()), "tree.json");
  ASSERT_EQ(back.segments.size(), tree.segments.size());
  for (std::size_t i = 0; i < tree.segments.size(); ++i) {
    EXPECT_EQ(back.segments[i].parent, tree.segments[i].parent);
    EXPECT_DOUBLE_EQ(back.segments[i].radius, tree.segments[i].radius);
    EXPECT_TRUE(back.segments[i].distal == tree.segments[i].distal);
  }
  auto broken = json;
  broken["tree"]["segments"][3]["parent"] = 9;
  try {
    vessel_tree_from_json(broken, "tree.json");
    FAIL();
  } catch (const core::ValidationError& e) {
    EXPECT_EQ(e.location().json_pointer, "/tree/segments/3/parent");
  }
}

TEST(VesselPipeMesh, a_bifurcation_gives_a_closed_outward_surface_of_the_right_volume) {
  core::VesselTree tree;
  tree.segments = {{0, -1, {0, 0, 0}, {0, 0, 0.02}, 0.002, 3e-6},
                   {1, 0, {0, 0, 0.02}, {0.012, 0, 0.035}, 0.0016, 1.5e-6},
                   {2, 0, {0, 0, 0.02}, {-0.012, 0, 0.035}, 0.0016, 1.5e-6}};
  const auto mesh = vessel_pipe_mesh(
      tree, {.voxel_size = 2e-4, .min_radius = 0.0, .blend = 0.6, .max_cells = 6'000'000});
  ASSERT_FALSE(mesh.triangles.empty());
  EXPECT_TRUE(core::is_closed_and_consistently_oriented(mesh));
  // Volume: the tubes with hemispherical caps, minus the overlap at the node, plus a small
  // fillet; within 8 % of the capsules' sum.
  double capsules = 0.0;
  for (const auto& s : tree.segments) {
    capsules += std::numbers::pi * s.radius * s.radius * segment_length(s) +
                4.0 / 3.0 * std::numbers::pi * std::pow(s.radius, 3);
  }
  EXPECT_GT(core::enclosed_volume(mesh), 0.0);  // outward orientation
  EXPECT_NEAR(core::enclosed_volume(mesh), capsules, 0.08 * capsules);
  // Every vertex lies on a wall: its distance to the nearest axis is about that segment's radius.
  for (const auto& v : mesh.vertices) {
    double wall = INFINITY;
    for (const auto& s : tree.segments) {
      wall = std::min(wall, segment_distance(v, v, s.proximal, s.distal) - s.radius);
    }
    ASSERT_LT(std::abs(wall), 0.001) << v.transpose();  // fillets stay within a millimetre
  }
}

TEST(VesselPipeMesh, meshes_a_grown_tree_watertight) {
  const SurfaceMeshDomain ball(core::make_icosphere(0.03, 2));
  CcoOptions options;
  options.terminals = 40;
  const auto mesh = vessel_pipe_mesh(grow_cco_tree(ball, options));
  EXPECT_TRUE(core::is_closed_and_consistently_oriented(mesh));
}

}  // namespace
}  // namespace viscera::templates
