#include "simulator/dynamics/plastic_flow.h"

#include <gtest/gtest.h>

#include <set>

#include "simulator/dynamics/backward_euler.h"
#include "simulator/dynamics/tissue_tearing.h"
#include "tests/simulator/authored_term_fixtures.h"

namespace viscera::sim {
namespace {

TEST(PlasticFlow, rest_lengths_follow_strain_only_past_the_yield) {
  const std::vector<core::Vec3> x = {core::Vec3::Zero(), core::Vec3(1.3, 0, 0),
                                     core::Vec3(2.3, 0, 0), core::Vec3(2.9, 0, 0),
                                     core::Vec3(3.0, 0, 0)};
  const std::vector<std::array<int, 2>> edges = {{0, 1}, {1, 2}, {2, 3}, {3, 4}};
  std::vector<double> rest = {1.0, 1.0, 1.0, 1.0};
  const std::vector<double> yield = {0.2, 0.2, 0.2, 0.0};
  EXPECT_EQ(apply_plastic_flow(x, edges, rest, yield), 2);
  EXPECT_DOUBLE_EQ(rest[0], 1.3 / 1.2);  // stretched 30 %: keeps 20 % elastic
  EXPECT_DOUBLE_EQ(rest[1], 1.0);        // exactly at rest
  EXPECT_DOUBLE_EQ(rest[2], 0.6 / 0.8);  // compressed 40 %: keeps 20 % elastic
  EXPECT_DOUBLE_EQ(rest[3], 1.0);        // no yield: never flows
}

/// An 8 × 1 × 1 bar of 5 mm cubes along x, held at x = 0, pulled at x = 4 cm with `load` N
/// for 1 s, then released for 2 s. Returns the free end's elongation over the bar's length
/// while loaded and after release; `tears` gets the tearing term's events.
struct Stretch {
  double loaded = 0.0, released = 0.0;
  long long flow_events = 0;
  std::vector<TearEvent> tears;
};
Stretch stretch_and_release(double plastic_yield, double load, double tear_strain = 10.0) {
  SimulationState state;
  core::Material material = testing::soft_test_material(200.0);
  material.plastic_yield = plastic_yield;
  material.tearing_threshold = tear_strain;
  const double length = 0.04;
  const auto model =
      testing::add_tet_body(state, "bar", testing::tet_block(8, 1, 1, 0.005), material,
                            [](const core::Vec3& p) { return p.x() < 1e-9; });
  auto distance = std::make_unique<TeschnerDistanceTerm>(model, state);
  auto volume = std::make_unique<TeschnerVolumeTerm>(model, state);
  auto plastic = std::make_unique<PlasticFlow>(BodyEdges(*distance), state);
  auto tearing = std::make_unique<TissueTearing>(BodyEdges(*distance), state);
  auto pull = std::make_unique<testing::TestLoad>();
  for (std::size_t i = 0; i < state.node_count(); ++i)
    if (state.rest_positions[i].x() > length - 1e-9) pull->nodes.push_back(static_cast<int>(i));
  pull->force = core::Vec3(load / static_cast<double>(pull->nodes.size()), 0.0, 0.0);
  const std::vector<ForceTerm*> terms = {distance.get(), volume.get(), pull.get(), plastic.get(),
                                         tearing.get()};
  BackwardEuler integrator;
  integrator.topology_changed(state, terms);
  const auto elongation = [&] {
    double sum = 0.0;
    for (const int n : pull->nodes)
      sum += state.positions[static_cast<std::size_t>(n)].x() - length;
    return sum / static_cast<double>(pull->nodes.size()) / length;
  };
  const double h = 1e-3;
  long long s = 0;
  Stretch out;
  for (; s < 1000; ++s)
    integrator.step(state, terms, {static_cast<double>(s) * h, h, s + 1});
  out.loaded = elongation();
  pull->force.setZero();
  for (; s < 3000; ++s)
    integrator.step(state, terms, {static_cast<double>(s) * h, h, s + 1});
  out.released = elongation();
  out.flow_events = plastic->flow_events();
  out.tears = tearing->tears();
  return out;
}

TEST(PlasticFlow, a_bar_stretched_past_the_yield_keeps_a_permanent_set) {
  const Stretch below = stretch_and_release(0.5, 0.4);
  const Stretch past = stretch_and_release(0.05, 0.4);
  // The same load stretches the bar well past 5 % but not near 50 %.
  EXPECT_GT(below.loaded, 0.1);
  EXPECT_LT(below.loaded, 0.4);
  // Below the yield it returns; past it the rest lengths grew and the set stays.
  EXPECT_EQ(below.flow_events, 0);
  EXPECT_LT(std::abs(below.released), 1e-3);
  EXPECT_GT(past.flow_events, 0);
  EXPECT_GT(past.released, 0.5 * (below.loaded - 0.05));
  EXPECT_LT(past.released, past.loaded);
  EXPECT_TRUE(below.tears.empty());
}

TEST(TissueTearing, edges_stretched_past_the_threshold_are_reported_once_with_their_strain) {
  const Stretch torn = stretch_and_release(0.5, 0.4, 0.1);
  ASSERT_FALSE(torn.tears.empty());
  std::set<std::pair<int, int>> seen;
  for (const auto& tear : torn.tears) {
    EXPECT_EQ(tear.body, "bar");
    EXPECT_GT(tear.strain, 0.1);
    EXPECT_DOUBLE_EQ(tear.threshold, 0.1);
    EXPECT_GT(tear.time, 0.0);
    EXPECT_LE(tear.time, 1.0 + 1e-9);  // while loaded
    EXPECT_TRUE(seen.insert({tear.node_a, tear.node_b}).second) << "reported twice";
  }
}

}  // namespace
}  // namespace viscera::sim
