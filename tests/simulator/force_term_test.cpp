// Every force term of the core: forces are minus the gradient of its energy and its exact
// Hessian is the derivative of its forces (central finite differences, relative 1e-5); its
// projected Hessian is positive semi-definite.
#include "simulator/dynamics/force_term.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <functional>
#include <memory>

#include "simulator/dynamics/attachment_term.h"
#include "simulator/dynamics/connection_spring_term.h"
#include "simulator/dynamics/contact_term.h"
#include "simulator/dynamics/gravity_term.h"
#include "simulator/dynamics/kismo_spring_term.h"
#include "simulator/dynamics/proxy_spring_term.h"
#include "simulator/dynamics/teschner_terms.h"
#include "tests/simulator/sim_fixtures.h"

namespace viscera::sim {
namespace {

/// Two small blocks: body 0 (2×2×2 of 1 cm) and body 1 (2×2×1 of 4 mm) above it at rest.
struct Scene {
  SimulationState state;
  std::vector<std::shared_ptr<const BodyModel>> models;
};

Scene two_bodies(const core::Material& material) {
  Scene s;
  core::TetMesh a = viscera::testing::tet_block(2, 2, 2, 0.01);
  core::TetMesh b = viscera::testing::tet_block(2, 2, 1, 0.004);
  for (auto& n : b.nodes)
    n += Vec3(0.001, 0.001, 0.025);
  for (const core::TetMesh* mesh : {&a, &b}) {
    auto model = viscera::testing::one_material_model(*mesh, material);
    model->body = s.state.add_body("b" + std::to_string(s.models.size()), mesh->nodes,
                                   core::lumped_node_masses(*mesh, material.density), {});
    s.models.push_back(model);
  }
  return s;
}

core::Material test_material() {
  core::Material m;
  m.distance_stiffness = 5000.0;
  m.volume_stiffness = 7000.0;
  m.area_stiffness = 3.0;
  m.distance_damping = 2.0;
  m.stress_strain = core::StressStrainCurve{{}, {}, {0.0, 4000.0, 9000.0, 30000.0}};
  return m;
}

/// The checks, at a deformed state x (velocities zero, so only −∇E counts).
void check_term(const ForceTerm& term, const SimulationState& state, std::vector<Vec3> x) {
  const std::size_t n = x.size();
  const std::vector<Vec3> zero(n, Vec3::Zero());
  std::vector<Vec3> f(n, Vec3::Zero());
  const double e = term.add_forces(x, zero, f);
  EXPECT_NEAR(e, term.energy(x), 1e-12 * std::max(1.0, std::abs(e))) << term.name();
  double largest = 0.0;
  for (const auto& v : f)
    largest = std::max(largest, v.norm());
  ASSERT_GT(largest, 0.0) << term.name() << ": the check needs a loaded state";
  BlockPattern pattern(n);
  term.declare_blocks(pattern);
  BlockSparseMatrix exact, projected;
  exact.set_pattern(pattern);
  projected.set_pattern(pattern);
  term.add_stiffness(x, 1.0, false, exact);
  term.add_stiffness(x, 1.0, true, projected);
  double largest_block = 0.0;
  for (std::size_t s = 0; s < exact.block_count(); ++s)
    largest_block = std::max(largest_block, exact.block(static_cast<int>(s)).cwiseAbs().maxCoeff());
  const double eps = 1e-7;
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) {
      auto plus = x, minus = x;
      plus[i][c] += eps;
      minus[i][c] -= eps;
      const double gradient = (term.energy(plus) - term.energy(minus)) / (2 * eps);
      ASSERT_NEAR(f[i][c], -gradient, 1e-5 * largest)
          << term.name() << " node " << i << " axis " << c;
      // Column (i, c) of the Hessian: −(f(x + ε e) − f(x − ε e)) / 2ε.
      std::vector<Vec3> fp(n, Vec3::Zero()), fm(n, Vec3::Zero());
      term.add_forces(plus, zero, fp);
      term.add_forces(minus, zero, fm);
      for (std::size_t j = 0; j < n; ++j) {
        const Vec3 column = -(fp[j] - fm[j]) / (2 * eps);
        const int slot = exact.slot(static_cast<int>(j), static_cast<int>(i));
        const Vec3 assembled = slot < 0 ? Vec3::Zero() : Vec3(exact.block(slot).col(c));
        ASSERT_LT((assembled - column).norm(), 1e-5 * largest_block + 1e-9)
            << term.name() << " block (" << j << ", " << i << ") column " << c;
      }
    }
  }
  // Projected: symmetric positive semi-definite (dense check over the touched nodes).
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(3 * static_cast<long>(n), 3 * static_cast<long>(n));
  for (std::size_t i = 0; i < n; ++i)
    for (const int j : projected.row_columns(static_cast<int>(i)))
      dense.block<3, 3>(3 * static_cast<long>(i), 3 * j) =
          projected.block(projected.slot(static_cast<int>(i), j));
  EXPECT_LT((dense - dense.transpose()).norm(), 1e-9 * std::max(1.0, dense.norm())) << term.name();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(dense);
  EXPECT_GT(solver.eigenvalues().minCoeff(), -1e-9 * std::max(1.0, dense.norm())) << term.name();
  (void)state;
}

std::vector<Vec3> deformed(const SimulationState& state, std::uint64_t seed) {
  std::vector<Vec3> x = state.positions;
  viscera::testing::jiggle(x, 0.0015, seed);
  return x;
}

TEST(ForceTerms, teschner_terms_are_consistent) {
  Scene s = two_bodies(test_material());
  check_term(TeschnerDistanceTerm(s.models[0], s.state), s.state, deformed(s.state, 1));
  check_term(TeschnerAreaTerm(s.models[0], s.state), s.state, deformed(s.state, 2));
  check_term(TeschnerVolumeTerm(s.models[0], s.state), s.state, deformed(s.state, 3));
}

TEST(ForceTerms, kismo_springs_are_consistent) {
  Scene s = two_bodies(test_material());
  check_term(KismoSpringTerm(s.models[1], s.state), s.state, deformed(s.state, 4));
}

TEST(ForceTerms, connection_springs_and_attachments_are_consistent) {
  Scene s = two_bodies(test_material());
  ConnectionSpringTerm springs({{0, 24, 1, 0, 300.0, 0.01}, {0, 25, 1, 1, 300.0, 0.0}}, s.state);
  check_term(springs, s.state, deformed(s.state, 5));
  Attachment a;
  a.body = 1;
  a.node = 2;
  a.host = 0;
  a.host_rest = Vec3(0.012, 0.007, 0.013);
  a.tet = locate_in_tets(s.models[0]->mesh, a.host_rest, a.weight);
  a.stiffness = 250.0;
  ASSERT_GE(a.tet, 0);
  EXPECT_NEAR(a.weight[0] + a.weight[1] + a.weight[2] + a.weight[3], 1.0, 1e-12);
  check_term(AttachmentTerm({a}, s.models, s.state), s.state, deformed(s.state, 6));
}

TEST(ForceTerms, gravity_is_consistent) {
  Scene s = two_bodies(test_material());
  check_term(GravityTerm(Vec3(0.0, 0.0, -9.81), s.state), s.state, deformed(s.state, 7));
}

TEST(ForceTerms, body_contact_is_consistent_and_conserves_momentum) {
  Scene s = two_bodies(test_material());
  BodyContactTerm contact(s.models, 500.0, s.state);
  // Sink the small block 3 mm into the large one: its bottom layer collides.
  const int first = s.state.body(1).first;
  for (int i = 0; i < s.state.body(1).count; ++i)
    s.state.positions[static_cast<std::size_t>(first + i)].z() -= 0.008;
  contact.prepare(s.state, {});
  EXPECT_EQ(contact.statistics().colliding_points, 9);
  EXPECT_NEAR(contact.statistics().max_penetration, 0.003, 1e-9);
  std::vector<Vec3> f(s.state.node_count(), Vec3::Zero());
  contact.add_forces(s.state.positions, s.state.velocities, f);
  Vec3 net = Vec3::Zero(), on_small = Vec3::Zero();
  for (std::size_t i = 0; i < f.size(); ++i) {
    net += f[i];
    if (static_cast<int>(i) >= first) on_small += f[i];
  }
  EXPECT_NEAR(on_small.z(), 9 * 500.0 * 0.003, 1e-9);  // every point pushed up by k·d
  EXPECT_LT(net.norm(), 1e-12);
  std::vector<Vec3> x = s.state.positions;
  viscera::testing::jiggle(x, 2e-4, 8);
  check_term(contact, s.state, x);
}

TEST(ForceTerms, overlaps_of_the_rest_configuration_are_not_contacts) {
  core::Material m = test_material();
  Scene s;
  core::TetMesh a = viscera::testing::tet_block(2, 2, 2, 0.01);
  core::TetMesh b = viscera::testing::tet_block(2, 2, 1, 0.004);
  for (auto& n : b.nodes)
    n += Vec3(0.001, 0.001, 0.017);  // its base sunk 3 mm into a
  for (const core::TetMesh* mesh : {&a, &b}) {
    auto model = viscera::testing::one_material_model(*mesh, m);
    model->body = s.state.add_body("b", mesh->nodes, core::lumped_node_masses(*mesh, 1000.0), {});
    s.models.push_back(model);
  }
  BodyContactTerm contact(s.models, 500.0, s.state);
  contact.prepare(s.state, {});
  EXPECT_EQ(contact.statistics().colliding_points, 0);
}

TEST(ForceTerms, the_instrument_proxy_spring_is_consistent_on_every_body) {
  Scene s = two_bodies(test_material());
  // The tip 1 mm under the top of the small block: the proxy meets the small body, not the big.
  const Vec3 above(0.005, 0.005, 0.04), inside(0.005, 0.005, 0.028);
  ProxySpringTerm proxy(s.models, 300.0, s.state, above);
  proxy.prepare(s.state, {});
  EXPECT_FALSE(proxy.proxy().in_contact());
  proxy.set_tip(inside);
  proxy.prepare(s.state, {});
  ASSERT_TRUE(proxy.proxy().in_contact());
  EXPECT_EQ(proxy.touched_body(), 1);
  EXPECT_NEAR(proxy.proxy().force().z(), 300.0 * 0.001, 1e-9);
  std::vector<Vec3> x = s.state.positions;
  viscera::testing::jiggle(x, 2e-4, 9);
  check_term(proxy, s.state, x);
}

}  // namespace
}  // namespace viscera::sim
