// The laparoscopic tools (issue 19 §3): the grasper's and the clip's force terms, and the
// tools at work on a fallopian tube of the laparoscopy-gyn template.
#include "simulator/session/laparoscopic_tools.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "simulator/dynamics/clip_term.h"
#include "simulator/dynamics/grasp_term.h"
#include "simulator/session/headless_session.h"
#include "simulator/session/instrument_input.h"
#include "templates/template_catalog.h"
#include "tests/simulator/term_derivative_checks.h"

namespace viscera::sim {
namespace {

/// Four free nodes of 1 g at the corners of a 2 cm square tilted out of the z = 0 plane.
SimulationState four_nodes() {
  SimulationState state;
  const std::vector<core::Vec3> rest = {
      {0.0, 0.0, 0.001}, {0.02, 0.0, -0.002}, {0.02, 0.02, 0.003}, {0.0, 0.02, -0.001}};
  const std::vector<double> mass(4, 1e-3);
  const std::vector<std::uint8_t> fixed(4, 0);
  state.add_body("tissue", rest, mass, fixed);
  return state;
}

std::vector<NodeReference> all_nodes(const SimulationState& state) {
  std::vector<NodeReference> out;
  for (int n = 0; n < 4; ++n)
    out.push_back(reference_node(state, 0, n));
  return out;
}

TEST(GraspTerm, forces_are_the_energy_gradient_and_the_jaws_feel_the_opposite) {
  SimulationState state = four_nodes();
  GraspTerm grasp(30.0, {0}, state);
  const core::Mat3 turn = Eigen::AngleAxisd(0.3, core::Vec3::UnitZ()).toRotationMatrix();
  grasp.hold(state, all_nodes(state), core::Vec3(0.01, 0.01, 0.0), turn);
  // Held where they were: no force until the jaws move.
  EXPECT_LT(grasp.force_on_jaws(state.positions).norm(), 1e-12);
  grasp.move_jaws(core::Vec3(0.01, 0.015, 0.002), turn);
  std::vector<core::Vec3> x = state.positions;
  x[2] += core::Vec3(0.001, -0.002, 0.0005);
  EXPECT_LT(testing::force_gradient_mismatch(grasp, x, 1e-7), 1e-6);
  EXPECT_LT(testing::hessian_force_mismatch(grasp, x, 1e-7), 1e-5);
  std::vector<core::Vec3> f(4, core::Vec3::Zero());
  const std::vector<core::Vec3> v(4, core::Vec3::Zero());
  grasp.add_forces(x, v, f);
  core::Vec3 on_tissue = core::Vec3::Zero();
  for (const auto& fi : f)
    on_tissue += fi;
  EXPECT_LT((on_tissue + grasp.force_on_jaws(x)).norm(), 1e-12);
  // The jaws moved 5 mm along +y and 2 mm up: the tissue is pulled that way.
  EXPECT_GT(on_tissue.y(), 0.0);
}

TEST(GraspTerm, a_knot_pulled_past_the_slip_force_tears_out_of_the_jaws) {
  SimulationState state = four_nodes();
  GraspTerm grasp(30.0, {0}, state);
  grasp.hold(state, all_nodes(state), core::Vec3::Zero(), core::Mat3::Identity());
  std::vector<core::Vec3> x = state.positions;
  x[1] += core::Vec3(0.05, 0.0, 0.0);  // 1.5 N on knot 1, none on the others
  EXPECT_NEAR(grasp.largest_node_force(x), 1.5, 1e-9);
  EXPECT_EQ(grasp.tear_out(x, 1.0), 1);
  ASSERT_EQ(grasp.held().size(), 3u);
  for (const auto& r : grasp.held())
    EXPECT_NE(r.node, 1);
  EXPECT_LT(grasp.largest_node_force(x), 1e-12);
}

TEST(ClipTerm, squeezes_along_its_jaws_and_conserves_momentum) {
  SimulationState state = four_nodes();
  ClipTerm clip(all_nodes(state), core::Vec3(0.0, 0.0, 2.0), 60.0, state);
  const auto& x = state.positions;
  EXPECT_LT(testing::force_gradient_mismatch(clip, x, 1e-7), 1e-6);
  EXPECT_LT(testing::hessian_force_mismatch(clip, x, 1e-7), 1e-5);
  std::vector<core::Vec3> f(4, core::Vec3::Zero());
  clip.add_forces(x, std::vector<core::Vec3>(4, core::Vec3::Zero()), f);
  core::Vec3 sum = core::Vec3::Zero();
  for (std::size_t i = 0; i < 4; ++i) {
    sum += f[i];
    // Only along the closing direction, towards the centre's height.
    EXPECT_NEAR(f[i].x(), 0.0, 1e-15);
    EXPECT_NEAR(f[i].y(), 0.0, 1e-15);
    EXPECT_LE(f[i].z() * (x[i].z() - clip.centre(x).z()), 0.0);
  }
  EXPECT_LT(sum.norm(), 1e-15);
  EXPECT_NEAR(clip.gap(x), 0.005, 1e-12);
  EXPECT_THROW(ClipTerm({reference_node(state, 0, 0)}, core::Vec3::UnitZ(), 60.0, state),
               core::UsageError);
}

TEST(NodeReference, a_reference_finds_its_node_again_after_the_body_is_renumbered) {
  SimulationState state = four_nodes();
  std::vector<NodeReference> refs = {reference_node(state, 0, 1), reference_node(state, 0, 3)};
  BodyNodeData data;
  // Renumbered in reverse, with one more node: 3 → 1, 1 → 3.
  data.rest = {{0.05, 0.0, 0.0},
               {0.0, 0.02, -0.001},
               {0.02, 0.02, 0.003},
               {0.02, 0.0, -0.002},
               {0.0, 0.0, 0.001}};
  data.positions = data.rest;
  data.masses.assign(5, 1e-3);
  state.replace_body_nodes(0, data);
  refind_nodes(state, 0, refs);
  ASSERT_EQ(refs.size(), 2u);
  EXPECT_EQ(refs[0].node, 3);
  EXPECT_EQ(refs[1].node, 1);
}

}  // namespace
}  // namespace viscera::sim
