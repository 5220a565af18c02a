// The laparoscopic tools' parts (issue 19 §3, §4): the grasper's and the clip's force terms,
// knots found again after a renumbering, and the smoke of coagulation with the lens steaming.
// The tools at work on a fallopian tube: sterilisation_session_test.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "simulator/dynamics/clip_term.h"
#include "simulator/dynamics/grasp_term.h"
#include "simulator/session/surgical_smoke.h"
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
  GraspTerm grasp(30.0);
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
  GraspTerm grasp(30.0);
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

/// Three nodes where a cut left two copies of one (nodes 0 and 1 share a rest position): node
/// 0 stayed in place, node 1 was carried 2 cm away (a chip drawn off the wall).
BodyNodeData carried_twin() {
  BodyNodeData data;
  data.rest = {{0.02, 0.0, -0.002}, {0.02, 0.0, -0.002}, {0.0, 0.02, -0.001}};
  data.positions = {{0.02, 0.0, -0.002}, {0.02, 0.0, 0.018}, {0.0, 0.02, -0.001}};
  data.masses.assign(3, 1e-3);
  return data;
}

TEST(NodeReference, of_two_copies_of_a_cut_node_the_reference_keeps_the_one_it_last_saw) {
  // A chip cut off earlier shares its rest positions with the wall it came from: here node 1's
  // twin (node 0, the lower index) stayed 2 cm away while node 1 was carried off.
  SimulationState state = four_nodes();
  BodyNodeData data = carried_twin();
  state.replace_body_nodes(0, data);
  std::vector<NodeReference> refs = {reference_node(state, 0, 1), reference_node(state, 0, 2)};
  EXPECT_EQ(refs[0].seen, core::Vec3(0.02, 0.0, 0.018));
  // Renumbered by a later cut (the carried copy is now last); the reference follows it.
  data.rest = {{0.02, 0.0, -0.002}, {0.0, 0.02, -0.001}, {0.02, 0.0, -0.002}};
  data.positions = {{0.02, 0.0, -0.002}, {0.0, 0.02, -0.001}, {0.02, 0.0, 0.0185}};
  state.replace_body_nodes(0, data);
  EXPECT_EQ(refind_nodes(state, 0, refs), (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(refs[0].node, 2);
  EXPECT_EQ(refs[1].node, 1);
  // A step brings it back beside its twin; note_positions records where, and refind keeps it.
  state.positions[2] = core::Vec3(0.02, 0.0, -0.0017);
  note_positions(state, refs);
  EXPECT_EQ(refs[0].seen, core::Vec3(0.02, 0.0, -0.0017));
  refind_nodes(state, 0, refs);
  EXPECT_EQ(refs[0].node, 2);
}

TEST(GraspTerm, a_cut_elsewhere_in_the_body_leaves_the_jaws_on_the_copies_they_hold) {
  // Jaws hold node 1, whose twin at the same rest position stays behind 2 cm away; a cut that
  // renumbers the body must not hand the jaws the twin (they would yank it across the cavity).
  SimulationState state = four_nodes();
  BodyNodeData data = carried_twin();
  state.replace_body_nodes(0, data);
  GraspTerm grasp(30.0);
  grasp.hold(state, {reference_node(state, 0, 1), reference_node(state, 0, 2)},
             core::Vec3(0.01, 0.01, 0.01), core::Mat3::Identity());
  grasp.after_step(state);
  data.rest.push_back({0.01, 0.01, 0.0});  // the cut's new node, appended
  data.positions.push_back({0.01, 0.01, 0.0});
  data.masses.push_back(1e-3);
  state.replace_body_nodes(0, data);
  grasp.topology_changed(state, 0);
  ASSERT_EQ(grasp.held().size(), 2u);
  EXPECT_EQ(grasp.held()[0].node, 1);
  EXPECT_EQ(grasp.held()[1].node, 2);
  EXPECT_NEAR(grasp.largest_node_force(state.positions), 0.0, 1e-12);
}

TEST(SurgicalSmoke, puffs_rise_grow_and_fade_and_the_same_steps_give_the_same_smoke) {
  const core::Vec3 up = core::Vec3::UnitZ(), site = core::Vec3::Zero();
  const core::Vec3 far_lens(0.5, 0.0, 0.0);
  SurgicalSmoke smoke, again;
  for (int k = 1; k <= 1000; ++k) {  // 1 s of coagulation
    smoke.step(0.001 * k, 0.001, site, up, far_lens);
    again.step(0.001 * k, 0.001, site, up, far_lens);
  }
  EXPECT_EQ(smoke.puffs_emitted(), 20);  // one every 50 ms
  const auto puffs = smoke.billboards();
  ASSERT_EQ(puffs.size(), 20u);
  // Born at 1 ms and 951 ms: risen 1 cm/s for 0.999 s and for 49 ms (the sway is across the
  // rise); the older has grown.
  EXPECT_NEAR(puffs.front().centre.z(), 0.00999, 1e-12);
  EXPECT_NEAR(puffs.back().centre.z(), 0.00049, 1e-12);
  EXPECT_GT(puffs.front().radius, puffs.back().radius);
  EXPECT_LT(std::hypot(puffs.back().centre.x(), puffs.back().centre.y()), 0.0002);
  for (std::size_t i = 0; i < puffs.size(); ++i) {
    EXPECT_EQ(puffs[i].centre, again.billboards()[i].centre);
    EXPECT_EQ(puffs[i].opacity, again.billboards()[i].opacity);
  }
  EXPECT_GT(smoke.smoke_time(), 0.5);
  EXPECT_EQ(smoke.lens_fog(), 0.0);  // the lens is half a metre away
  // No more current: every puff has faded after its 6 s of life.
  for (int k = 1001; k <= 8000; ++k)
    smoke.step(0.001 * k, 0.001, std::nullopt, up, far_lens);
  EXPECT_TRUE(smoke.billboards().empty());
}

TEST(SurgicalSmoke,
     the_lens_steams_up_near_hot_tissue_and_clears_with_time_and_suction_clears_smoke) {
  const core::Vec3 up = core::Vec3::UnitZ(), site = core::Vec3::Zero();
  const core::Vec3 lens(0.0, -0.02, 0.0);  // 2 cm from the coagulation
  SurgicalSmoke smoke;
  for (int k = 1; k <= 4000; ++k)
    smoke.step(0.001 * k, 0.001, site, up, lens);
  const double steamed = smoke.lens_fog();
  EXPECT_GT(steamed, 0.4);
  for (int k = 4001; k <= 10000; ++k)  // 6 s without current: e⁻¹ of the fog left, at most
    smoke.step(0.001 * k, 0.001, std::nullopt, up, lens);
  EXPECT_LT(smoke.lens_fog(), steamed * std::exp(-1.0) + 1e-9);
  EXPECT_NEAR(smoke.peak_lens_fog(), steamed, 1e-3);
  // Suction at the column removes the puffs near its tip and no others.
  SurgicalSmoke column;
  for (int k = 1; k <= 2000; ++k)
    column.step(0.001 * k, 0.001, site, up, lens);
  const auto before = column.billboards().size();
  const int removed = column.suck(core::Vec3(0.0, 0.0, 0.005), 0.004, 2.0);
  EXPECT_GT(removed, 0);
  EXPECT_EQ(column.billboards().size(), before - static_cast<std::size_t>(removed));
  for (const auto& b : column.billboards())
    EXPECT_GT((b.centre - core::Vec3(0.0, 0.0, 0.005)).norm(), 0.004);
}

}  // namespace
}  // namespace viscera::sim
