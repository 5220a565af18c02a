#include "simulator/dynamics/plastic_flow.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "simulator/dynamics/backward_euler.h"
#include "simulator/dynamics/body_edges.h"
#include "simulator/dynamics/kismo_spring_term.h"
#include "simulator/dynamics/tissue_tearing.h"
#include "tests/simulator/authored_term_fixtures.h"

namespace viscera::sim {
namespace {

TEST(PlasticFlow, rest_lengths_follow_stretch_only_past_the_yield_and_stop_at_the_tear) {
  const std::vector<core::Vec3> x = {core::Vec3::Zero(),    core::Vec3(1.3, 0, 0),
                                     core::Vec3(2.3, 0, 0), core::Vec3(2.9, 0, 0),
                                     core::Vec3(3.0, 0, 0), core::Vec3(6.0, 0, 0)};
  const std::vector<std::array<int, 2>> edges = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}};
  std::vector<double> rest = {1.0, 1.0, 1.0, 1.0, 1.0};
  const std::vector<double> yield = {0.2, 0.2, 0.2, 0.0, 0.2};
  const std::vector<double> longest(5, 2.0);
  EXPECT_EQ(apply_plastic_flow(x, edges, rest, yield, longest), 2);
  EXPECT_DOUBLE_EQ(rest[0], 1.3 / 1.2);  // stretched 30 %: keeps 20 % elastic
  EXPECT_DOUBLE_EQ(rest[1], 1.0);        // exactly at rest
  EXPECT_DOUBLE_EQ(rest[2], 1.0);        // compressed 40 %: only stretch flows
  EXPECT_DOUBLE_EQ(rest[3], 1.0);        // no yield: never flows
  EXPECT_DOUBLE_EQ(rest[4], 2.0);        // 3 would be 2.5, but it tore at 2
}

TEST(BodyEdges, an_edge_takes_the_weakest_limit_of_the_layers_that_share_it) {
  // A 4 × 1 × 1 bar: tets left of x = 1 cm are the weak layer (yield 0.1), the rest strong (0.3).
  SimulationState state;
  const std::vector<core::Vec3> one_node = {core::Vec3::Zero()};
  const std::vector<double> one_mass = {1.0};
  const std::vector<std::uint8_t> not_fixed = {0};
  state.add_body("before", one_node, one_mass, not_fixed);  // the bar's nodes start at 1
  core::Material weak = testing::soft_test_material(200.0), strong = weak;
  weak.plastic_yield = 0.1;
  strong.plastic_yield = 0.3;
  const auto model = testing::add_tet_body(state, "bar", testing::tet_block(4, 1, 1, 0.005), strong,
                                           [](const core::Vec3&) { return false; });
  model->materials = {weak, strong};
  const auto& mesh = model->mesh;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    double x = 0.0;
    for (const int v : mesh.tets[t])
      x += 0.25 * mesh.nodes[static_cast<std::size_t>(v)].x();
    model->tet_material[t] = x < 0.01 ? 0 : 1;
  }
  TeschnerDistanceTerm distance(model, state);
  const BodyEdges edges(distance);
  const int first = state.body(model->body).first;
  ASSERT_EQ(first, 1);
  const auto yield = edges.material_limit(&core::Material::plastic_yield, first);
  ASSERT_EQ(yield.size(), edges.edges().size());
  int weak_edges = 0, strong_edges = 0;
  for (std::size_t e = 0; e < yield.size(); ++e) {
    const auto [a, b] = edges.edges()[e];
    // Which layers hold the edge, from the tets that have both its nodes.
    bool in_weak = false, in_strong = false;
    for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
      const auto& tet = mesh.tets[t];
      const bool has_a = std::find(tet.begin(), tet.end(), a - first) != tet.end();
      const bool has_b = std::find(tet.begin(), tet.end(), b - first) != tet.end();
      if (!has_a || !has_b) continue;
      (model->tet_material[t] == 0 ? in_weak : in_strong) = true;
    }
    ASSERT_TRUE(in_weak || in_strong);
    EXPECT_DOUBLE_EQ(yield[e], in_weak ? 0.1 : 0.3);
    (in_weak ? weak_edges : strong_edges) += 1;
  }
  EXPECT_GT(weak_edges, 10);
  EXPECT_GT(strong_edges, 10);
  // One layer: every edge has its value.
  model->materials = {strong, strong};
  for (const double y : edges.material_limit(&core::Material::plastic_yield, first))
    EXPECT_DOUBLE_EQ(y, 0.3);
}

/// An 8 × 1 × 1 bar of 5 mm cubes along x, held at x = 0; its x = 4 cm face is pulled out by
/// `stretch` × 4 cm over 0.5 s, held there 0.5 s, then let go for 2 s. Returns the free end's
/// mean elongation over the bar's length while held and after release, and what the plastic
/// and tearing terms saw.
struct Stretch {
  double held = 0.0, released = 0.0;
  long long flow_events = 0;
  std::vector<TearEvent> tears;
};
Stretch stretch_and_release(double plastic_yield, double stretch, double tear_strain = 10.0,
                            bool mass_spring = false) {
  SimulationState state;
  core::Material material = testing::soft_test_material(200.0);
  material.plastic_yield = plastic_yield;
  material.tearing_threshold = tear_strain;
  const double length = 0.04;
  const auto model = testing::add_tet_body(
      state, "bar", testing::tet_block(8, 1, 1, 0.005), material,
      [&](const core::Vec3& p) { return p.x() < 1e-9 || p.x() > length - 1e-9; });
  // Teschner distance and volume terms, or a KisMo net of cubic springs on the tet edges.
  model->kind = mass_spring ? BodyModelKind::KismoMassSpring : BodyModelKind::Teschner;
  std::vector<std::unique_ptr<ForceTerm>> owned;
  std::unique_ptr<PlasticFlow> plastic;
  std::unique_ptr<TissueTearing> tearing;
  if (mass_spring) {
    auto springs = std::make_unique<KismoSpringTerm>(model, state);
    plastic = std::make_unique<PlasticFlow>(BodyEdges(*springs), state);
    tearing = std::make_unique<TissueTearing>(BodyEdges(*springs), state);
    owned.push_back(std::move(springs));
  } else {
    auto distance = std::make_unique<TeschnerDistanceTerm>(model, state);
    plastic = std::make_unique<PlasticFlow>(BodyEdges(*distance), state);
    tearing = std::make_unique<TissueTearing>(BodyEdges(*distance), state);
    owned.push_back(std::move(distance));
    owned.push_back(std::make_unique<TeschnerVolumeTerm>(model, state));
  }
  std::vector<std::size_t> end;
  for (std::size_t i = 0; i < state.node_count(); ++i)
    if (state.rest_positions[i].x() > length - 1e-9) end.push_back(i);
  std::vector<ForceTerm*> terms;
  for (const auto& t : owned)
    terms.push_back(t.get());
  terms.push_back(plastic.get());
  terms.push_back(tearing.get());
  BackwardEuler integrator;
  integrator.topology_changed(state, terms);
  const auto elongation = [&] {
    double sum = 0.0;
    for (const std::size_t n : end)
      sum += state.positions[n].x() - length;
    return sum / static_cast<double>(end.size()) / length;
  };
  const double h = 1e-3;
  Stretch out;
  for (long long s = 0; s < 3000; ++s) {
    if (s < 500)
      for (const std::size_t n : end)
        state.positions[n].x() = length * (1.0 + stretch * static_cast<double>(s + 1) / 500.0);
    if (s == 1000) {
      out.held = elongation();
      for (const std::size_t n : end)
        state.inverse_masses[n] = 1.0 / state.masses[n];
    }
    integrator.step(state, terms, {static_cast<double>(s) * h, h, s + 1});
  }
  out.released = elongation();
  out.flow_events = plastic->flow_events();
  out.tears = tearing->tears();
  return out;
}

TEST(PlasticFlow, a_bar_stretched_past_the_yield_keeps_a_permanent_set) {
  const Stretch below = stretch_and_release(0.5, 0.2);
  const Stretch past = stretch_and_release(0.05, 0.2);
  EXPECT_NEAR(below.held, 0.2, 1e-9);
  // Below the yield nothing flows and the bar returns; past it the set stays.
  EXPECT_EQ(below.flow_events, 0);
  EXPECT_LT(std::abs(below.released), 1e-3);
  EXPECT_GT(past.flow_events, 0);
  EXPECT_GT(past.released, 0.05);
  EXPECT_LT(past.released, 0.2);
  EXPECT_TRUE(below.tears.empty());
}

TEST(PlasticFlow, a_kismo_net_stretched_past_the_yield_keeps_a_permanent_set_too) {
  const Stretch below = stretch_and_release(0.5, 0.2, 10.0, true);
  const Stretch past = stretch_and_release(0.05, 0.2, 10.0, true);
  EXPECT_EQ(below.flow_events, 0);
  EXPECT_LT(std::abs(below.released), 1e-3);
  EXPECT_GT(past.flow_events, 0);
  EXPECT_GT(past.released, 0.05);
  EXPECT_LT(past.released, 0.2);
}

TEST(TissueTearing, edges_stretched_past_the_threshold_are_reported_once_with_their_strain) {
  const Stretch torn = stretch_and_release(0.5, 0.2, 0.1);
  ASSERT_FALSE(torn.tears.empty());
  std::set<std::pair<int, int>> seen;
  for (const auto& tear : torn.tears) {
    EXPECT_EQ(tear.body, "bar");
    EXPECT_GT(tear.strain, 0.1);
    EXPECT_DOUBLE_EQ(tear.threshold, 0.1);
    EXPECT_GT(tear.time, 0.0);
    EXPECT_LE(tear.time, 0.5 + 1e-9);  // while being stretched
    EXPECT_TRUE(seen.insert({tear.node_a, tear.node_b}).second) << "reported twice";
  }
}

}  // namespace
}  // namespace viscera::sim
