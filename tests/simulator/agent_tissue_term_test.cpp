#include "simulator/dynamics/agent_tissue_term.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/random.h"
#include "simulator/dynamics/explicit_verlet.h"
#include "tests/simulator/authored_term_fixtures.h"
#include "tests/simulator/term_derivative_checks.h"

namespace viscera::sim {
namespace {

/// An n × n sheet of cells 1 mm apart at z = 0 (two types in stripes), its y = 0 row held,
/// after a first body of two nodes so its node range starts at 2.
struct Sheet {
  SimulationState state;
  std::shared_ptr<BodyModel> model;
  core::CellTissueSpec spec;
};
Sheet sheet(int n) {
  Sheet s;
  s.spec.object = "tissue";
  core::CellTypeSpec soft, stiff;
  soft.id = "matrix";
  stiff.id = "inclusion";
  stiff.connection_stiffness = 60.0;
  stiff.home_stiffness = 1.0;
  s.spec.types = {soft, stiff};
  s.spec.neighbour_radius = 0.00105;
  s.model = std::make_shared<BodyModel>();
  s.model->name = "tissue";
  s.model->kind = BodyModelKind::CellAgent;
  std::vector<double> mass;
  std::vector<std::uint8_t> fixed;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      s.model->mesh.nodes.emplace_back(0.001 * i, 0.001 * j, 0.0);
      s.spec.cell_types.push_back((j / 2) % 2);
      mass.push_back(1e-4);
      fixed.push_back(j == 0 ? 1 : 0);
    }
  s.state.add_body("other", std::vector<core::Vec3>{core::Vec3(1, 0, 0), core::Vec3(2, 0, 0)},
                   std::vector<double>(2, 1.0), {});
  s.model->body = s.state.add_body("tissue", s.model->mesh.nodes, mass, fixed);
  return s;
}

std::vector<core::Vec3> jiggled(std::vector<core::Vec3> x, double amplitude) {
  core::Rng rng(11);
  for (auto& p : x)
    p += core::Vec3(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)) *
         amplitude;
  return x;
}

TEST(AgentTissueTerm, forces_are_the_energy_gradient_and_the_hessian_their_derivative) {
  Sheet s = sheet(4);
  AgentTissueTerm term(s.model, s.state, s.spec, 5e-4);
  EXPECT_EQ(term.connections().size(), 24u);  // 2 · 4 · 3 grid links
  const auto x = jiggled(s.state.positions, 3e-4);
  EXPECT_LT(testing::force_gradient_mismatch(term, x, 1e-8), 1e-6);
  EXPECT_LT(testing::hessian_force_mismatch(term, x, 1e-8), 1e-5);
  EXPECT_GE(testing::smallest_projected_eigenvalue(term, x), -1e-9);
  // Damping of eq. 6: b per step of h is the viscous coefficient m b / h.
  EXPECT_DOUBLE_EQ(term.damping(5), 1e-4 * 0.05 / 5e-4);
}

TEST(AgentTissueTerm, connections_past_their_tear_strain_break_and_are_recorded) {
  Sheet s = sheet(4);
  AgentTissueTerm term(s.model, s.state, s.spec, 5e-4);
  const int first = s.state.body(s.model->body).first;
  // Cell (3, 3) pulled 2.5 mm out of the sheet: its two links stretch by 169 % (tear 100 %).
  const int corner = 15;
  s.state.positions[static_cast<std::size_t>(first + corner)].z() = 0.0025;
  s.state.time = 0.25;
  term.after_step(s.state);
  ASSERT_EQ(term.tears().size(), 2u);
  for (const auto& tear : term.tears()) {
    EXPECT_TRUE(tear.node_a == corner || tear.node_b == corner);
    EXPECT_NEAR(tear.strain, std::hypot(1.0, 2.5) - 1.0, 1e-9);
    EXPECT_DOUBLE_EQ(tear.threshold, 1.0);
    EXPECT_DOUBLE_EQ(tear.time, 0.25);
  }
  EXPECT_EQ(term.connections().size(), 22u);
  // Cell (1, 2) lifted 1.2 mm: its links stretch 56 %, past the 50 % yield, so they lengthen.
  const int lifted = 9;
  s.state.positions[static_cast<std::size_t>(first + lifted)].z() = 0.0012;
  term.after_step(s.state);
  EXPECT_EQ(term.tears().size(), 2u);
  int grown = 0;
  for (const auto& c : term.connections()) {
    if (c.a != lifted && c.b != lifted) continue;
    EXPECT_NEAR(c.rest_length, std::hypot(1.0, 1.2) * 1e-3 / 1.5, 1e-12);
    EXPECT_DOUBLE_EQ(c.original_length, 0.001);
    ++grown;
  }
  EXPECT_EQ(grown, 4);
}

TEST(AgentTissueTerm, a_pressed_sheet_springs_back_home_under_the_explicit_integrator) {
  Sheet s = sheet(6);
  auto term = std::make_unique<AgentTissueTerm>(s.model, s.state, s.spec, 5e-4);
  auto press = std::make_unique<testing::TestLoad>();
  const int first = s.state.body(s.model->body).first;
  press->nodes = {first + 3 * 6 + 3};
  press->force = core::Vec3(0.0, 0.0, -0.01);
  const std::vector<ForceTerm*> terms = {term.get(), press.get()};
  ExplicitVerlet integrator;
  integrator.topology_changed(s.state, terms);
  const double h = 5e-4;
  long long step = 0;
  for (; step < 400; ++step)
    integrator.step(s.state, terms, {step * h, h, step + 1});
  const std::size_t pressed = static_cast<std::size_t>(press->nodes[0]);
  EXPECT_LT(s.state.positions[pressed].z(), -1e-4);  // it gave way out of its plane
  press->force.setZero();
  for (; step < 4000; ++step)
    integrator.step(s.state, terms, {step * h, h, step + 1});
  double farthest = 0.0;
  for (std::size_t i = static_cast<std::size_t>(first); i < s.state.node_count(); ++i)
    farthest = std::max(farthest, (s.state.positions[i] - s.state.rest_positions[i]).norm());
  EXPECT_LT(farthest, 1e-6);
  EXPECT_TRUE(term->tears().empty());
}

TEST(AgentTissueTerm, a_blade_through_the_sheet_cuts_the_links_it_crosses) {
  Sheet s = sheet(4);
  AgentTissueTerm term(s.model, s.state, s.spec, 5e-4);
  // A vertical blade along x = 1.5 mm across the whole sheet cuts the 4 links crossing it.
  const int cut = term.cut(s.state, core::Vec3(0.0015, -0.001, -0.001),
                           core::Vec3(0.0015, 0.01, -0.001), core::Vec3(0.0015, -0.001, 0.01));
  EXPECT_EQ(cut, 4);
  EXPECT_EQ(term.connections().size(), 20u);
}

TEST(AgentTissueTerm, names_the_object_when_cells_and_types_disagree) {
  Sheet s = sheet(3);
  s.spec.cell_types.pop_back();
  try {
    AgentTissueTerm(s.model, s.state, s.spec, 5e-4);
    FAIL() << "a missing cell type was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tissue"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace viscera::sim
