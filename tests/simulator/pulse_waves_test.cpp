#include "simulator/dynamics/pulse_waves.h"

#include <gtest/gtest.h>

#include <map>

#include "core/error.h"
#include "tests/simulator/authored_term_fixtures.h"
#include "tests/simulator/term_derivative_checks.h"

namespace viscera::sim {
namespace {

/// A branching tree in the z = 0 plane: a 20 mm root along +x, two 22.4 mm daughters up and
/// down from its end, and a 10 mm grand-daughter at the end of the upper one.
core::VesselTree branching_tree() {
  core::VesselTree tree;
  tree.id = "arteries";
  tree.host_object = "host";
  const core::Vec3 root_end(0.02, 0.0, 0.0), up_end(0.04, 0.01, 0.0), down_end(0.04, -0.01, 0.0);
  tree.segments = {{0, -1, core::Vec3::Zero(), root_end, 0.001, 0.0},
                   {1, 0, root_end, up_end, 0.0008, 0.0},
                   {2, 0, root_end, down_end, 0.0008, 0.0},
                   {3, 1, up_end, up_end + core::Vec3(0.01, 0.0, 0.0), 0.0005, 0.0}};
  return tree;
}

/// Host nodes 1 mm above (+z) points every 2 mm along each segment of `tree`, excluding the
/// shared proximal ends of daughters; also returns each node's path length from the root.
struct Host {
  std::vector<core::Vec3> nodes;
  std::vector<double> path_length;
};
Host host_along(const core::VesselTree& tree) {
  Host host;
  const std::vector<double> start = {0.0, 0.02, 0.02, 0.02 + std::hypot(0.02, 0.01)};
  for (std::size_t s = 0; s < tree.segments.size(); ++s) {
    const auto& seg = tree.segments[s];
    const double length = (seg.distal - seg.proximal).norm();
    for (double along = s == 0 ? 0.0 : 0.002; along <= length + 1e-12; along += 0.002) {
      const core::Vec3 axis_point = seg.proximal + along / length * (seg.distal - seg.proximal);
      host.nodes.push_back(axis_point + core::Vec3(0.0, 0.0, 0.001));
      host.path_length.push_back(start[s] + along);
    }
  }
  return host;
}

struct PulseSetup {
  SimulationState state;
  std::shared_ptr<BodyModel> model;
  Host host;
};

PulseSetup pulse_setup(const core::VesselTree& tree) {
  PulseSetup setup;
  setup.host = host_along(tree);
  setup.model = std::make_shared<BodyModel>();
  setup.model->name = "host";
  setup.model->mesh.nodes = setup.host.nodes;
  setup.model->materials = {core::Material{}};
  const std::vector<double> mass(setup.host.nodes.size(), 1e-4);
  // A first body in front, so the host's node range does not start at 0.
  const std::vector<core::Vec3> other = {core::Vec3(1, 1, 1), core::Vec3(1, 1, 2)};
  setup.state.add_body("other", other, std::vector<double>(2, 1e-4), {});
  setup.model->body = setup.state.add_body("host", setup.host.nodes, mass, {});
  return setup;
}

TEST(VesselWavePaths, proximal_arcs_sum_the_ancestors_so_daughters_share_their_start) {
  const auto arc = proximal_arc_lengths(branching_tree());
  ASSERT_EQ(arc.size(), 4u);
  EXPECT_DOUBLE_EQ(arc[0], 0.0);
  EXPECT_DOUBLE_EQ(arc[1], 0.02);
  EXPECT_DOUBLE_EQ(arc[2], 0.02);  // the wave is duplicated at the bifurcation
  EXPECT_NEAR(arc[3], 0.02 + std::hypot(0.02, 0.01), 1e-15);
}

TEST(VesselWavePaths, names_the_tree_and_segment_of_a_bad_parent_or_a_cycle) {
  core::VesselTree bad = branching_tree();
  bad.segments[2].parent = 7;
  try {
    proximal_arc_lengths(bad);
    FAIL() << "a parent out of range was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("arteries"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("segment 2"), std::string::npos) << e.what();
  }
  core::VesselTree cycle = branching_tree();
  cycle.segments[0].parent = 3;
  EXPECT_THROW(proximal_arc_lengths(cycle), core::InputError);
}

TEST(VesselWavePaths, wall_knots_are_the_nearest_nodes_with_their_path_length_and_radial_push) {
  const core::VesselTree tree = branching_tree();
  const Host host = host_along(tree);
  const auto knots = pulse_wall_knots(tree, host.nodes, 0.001);
  ASSERT_EQ(knots.size(), host.nodes.size());  // every node lies 1 mm over some axis
  for (const auto& k : knots) {
    EXPECT_NEAR(k.arc, host.path_length[static_cast<std::size_t>(k.node)], 1e-12) << k.node;
    EXPECT_TRUE(k.direction.isApprox(core::Vec3::UnitZ(), 1e-9)) << k.node;
  }
  for (std::size_t i = 1; i < knots.size(); ++i)
    EXPECT_LE(knots[i - 1].arc, knots[i].arc);
}

TEST(PulseWaves, a_wave_reaches_each_knot_at_its_path_length_over_the_wave_speed) {
  PulseSetup setup = pulse_setup(branching_tree());
  const core::PulseSpec spec{"arteries", 60.0, 2.0, 0.05};  // one beat per second, 2 m/s
  PulseWaves pulse(setup.model, setup.state, spec, branching_tree(), "pulse");
  const double h = 1e-3;
  const int first = setup.state.body(setup.model->body).first;
  std::map<int, long long> arrival;  // body node → first step pushed
  std::map<int, int> pushes;
  for (long long s = 0; s < 1000; ++s) {  // exactly one beat
    pulse.prepare(setup.state, {static_cast<double>(s) * h, h, s + 1});
    for (const int g : pulse.pushed()) {
      arrival.try_emplace(g - first, s);
      ++pushes[g - first];
    }
  }
  ASSERT_EQ(arrival.size(), setup.host.nodes.size());
  for (const auto& [node, step] : arrival) {
    const double expected = setup.host.path_length[static_cast<std::size_t>(node)] / 2.0;
    EXPECT_LE(static_cast<double>(step) * h, expected + 1e-12) << node;
    EXPECT_GT(static_cast<double>(step + 1) * h, expected - 1e-12) << node;
    EXPECT_EQ(pushes[node], 1) << "the second wave removes the force after one step";
  }
  // Duplicated at the bifurcation: 10 mm down both daughters at the same step.
  const auto at = [&](double path, double y_sign) {
    for (std::size_t i = 0; i < setup.host.nodes.size(); ++i)
      if (std::abs(setup.host.path_length[i] - path) < 1e-9 &&
          setup.host.nodes[i].y() * y_sign > 0.0)
        return static_cast<int>(i);
    return -1;
  };
  const double daughter = 0.02 + 0.01;
  ASSERT_GE(at(daughter, 1.0), 0);
  ASSERT_GE(at(daughter, -1.0), 0);
  EXPECT_EQ(arrival[at(daughter, 1.0)], arrival[at(daughter, -1.0)]);
  // The next beat starts again at the root.
  pulse.prepare(setup.state, {1.0, h, 1001});
  ASSERT_FALSE(pulse.pushed().empty());
  EXPECT_EQ(pulse.pushed().front() - first, 0);
}

TEST(PulseWaves, a_clip_stops_the_wave_downstream_and_not_upstream_or_on_the_sister_branch) {
  PulseSetup setup = pulse_setup(branching_tree());
  const core::PulseSpec spec{"arteries", 60.0, 2.0, 0.05};
  PulseWaves pulse(setup.model, setup.state, spec, branching_tree(), "pulse");
  pulse.occlude(1, 0.01);  // 10 mm down the upper daughter: hierarchy arc 30 mm
  const int first = setup.state.body(setup.model->body).first;
  std::map<int, int> pushes;
  for (long long s = 0; s < 1000; ++s) {  // one beat
    pulse.prepare(setup.state, {static_cast<double>(s) * 1e-3, 1e-3, s + 1});
    for (const int g : pulse.pushed())
      ++pushes[g - first];
  }
  int upstream = 0, downstream = 0;
  for (std::size_t n = 0; n < setup.host.nodes.size(); ++n) {
    const double path = setup.host.path_length[n];
    const bool upper = setup.host.nodes[n].y() > 1e-9;  // the upper daughter and its daughter
    const bool behind_clip = upper && path > 0.03 + 1e-9;
    if (behind_clip) {
      EXPECT_EQ(pushes.count(static_cast<int>(n)), 0u) << "pushed behind the clip: " << path;
      ++downstream;
    } else {
      EXPECT_EQ(pushes[static_cast<int>(n)], 1) << "not reached before the clip: " << path;
      ++upstream;
    }
  }
  EXPECT_GT(downstream, 5);  // the rest of the upper daughter and all of the grand-daughter
  EXPECT_GT(upstream, 20);
  EXPECT_THROW(pulse.occlude(4, 0.0), core::UsageError);
  EXPECT_THROW(pulse.occlude(1, 0.03), core::UsageError);  // the daughter is 22.4 mm long
}

TEST(PulseWaves, occluding_at_a_point_clips_where_the_point_projects_on_the_segment_axis) {
  PulseSetup setup = pulse_setup(branching_tree());
  const core::PulseSpec spec{"arteries", 60.0, 2.0, 0.05};
  PulseWaves by_length(setup.model, setup.state, spec, branching_tree(), "pulse");
  PulseWaves by_point(setup.model, setup.state, spec, branching_tree(), "pulse");
  by_length.occlude(1, 0.01);
  // 10 mm down the upper daughter from (20, 0, 0) mm along (20, 10, 0)/|…|, 1 mm off its axis.
  const core::Vec3 dir = core::Vec3(0.02, 0.01, 0.0).normalized();
  by_point.occlude_at(1, core::Vec3(0.02, 0.0, 0.0) + 0.01 * dir + core::Vec3(0.0, 0.0, 0.001));
  EXPECT_EQ(by_point.vessel_tree(), "arteries");
  int blocked = 0;
  for (std::size_t k = 0; k < by_length.knots().size(); ++k) {
    EXPECT_EQ(by_point.reaches(k), by_length.reaches(k)) << k;
    blocked += !by_point.reaches(k);
  }
  EXPECT_GT(blocked, 0);
  EXPECT_THROW(by_point.occlude_at(7, core::Vec3::Zero()), core::UsageError);
}

TEST(PulseWaves, pushes_with_the_wall_force_outward_and_its_forces_are_the_energy_gradient) {
  PulseSetup setup = pulse_setup(branching_tree());
  const core::PulseSpec spec{"arteries", 60.0, 2.0, 0.05};
  PulseWaves pulse(setup.model, setup.state, spec, branching_tree(), "pulse");
  pulse.prepare(setup.state, {0.0105, 1e-3, 11});  // the front sweeps 21–23 mm
  ASSERT_FALSE(pulse.pushed().empty());
  std::vector<core::Vec3> f(setup.state.node_count(), core::Vec3::Zero());
  const std::vector<core::Vec3> v(setup.state.node_count(), core::Vec3::Zero());
  pulse.add_forces(setup.state.positions, v, f);
  for (const int g : pulse.pushed())
    EXPECT_TRUE(f[static_cast<std::size_t>(g)].isApprox(core::Vec3(0.0, 0.0, 0.05), 1e-12));
  EXPECT_LT(testing::force_gradient_mismatch(pulse, setup.state.positions, 1e-6), 1e-8);
  EXPECT_LT(testing::hessian_force_mismatch(pulse, setup.state.positions, 1e-6), 1e-8);
}

TEST(PulseWaves, a_new_beat_deletes_the_wave_still_running) {
  PulseSetup setup = pulse_setup(branching_tree());
  // 600 beats/min: 0.1 s per beat at 0.25 m/s reaches 25 mm; the tree is 52 mm deep.
  const core::PulseSpec spec{"arteries", 600.0, 0.25, 0.05};
  PulseWaves pulse(setup.model, setup.state, spec, branching_tree(), "pulse");
  const int first = setup.state.body(setup.model->body).first;
  double furthest = 0.0;
  for (long long s = 0; s < 300; ++s) {
    pulse.prepare(setup.state, {static_cast<double>(s) * 1e-3, 1e-3, s + 1});
    for (const int g : pulse.pushed())
      furthest = std::max(furthest, setup.host.path_length[static_cast<std::size_t>(g - first)]);
  }
  EXPECT_LT(furthest, 0.025);
  EXPECT_GT(furthest, 0.02);
}

TEST(PulseWaves, refuses_a_heart_rate_or_velocity_that_is_not_positive) {
  PulseSetup setup = pulse_setup(branching_tree());
  EXPECT_THROW(
      PulseWaves(setup.model, setup.state, {"arteries", 0.0, 2.0, 0.05}, branching_tree(), "p"),
      core::InputError);
  EXPECT_THROW(
      PulseWaves(setup.model, setup.state, {"arteries", 60.0, -1.0, 0.05}, branching_tree(), "p"),
      core::InputError);
}

}  // namespace
}  // namespace viscera::sim
