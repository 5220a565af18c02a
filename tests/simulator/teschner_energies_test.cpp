#include "simulator/physics/teschner_energies.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "simulator/dynamics/explicit_verlet.h"
#include "tests/simulator/sim_fixtures.h"

namespace viscera::sim {
namespace {

/// A 2×2×2 block with all three kinds of terms, deformed at random.
struct Deformed {
  viscera::testing::TeschnerBody body;
  std::vector<Vec3> x;
};

Deformed deformed_block(std::uint64_t seed) {
  core::Material material;
  material.distance_stiffness = 5000.0;
  material.area_stiffness = 3.0;
  material.volume_stiffness = 7000.0;
  material.distance_damping = 0.0;
  Deformed d{viscera::testing::TeschnerBody(viscera::testing::tet_block(2, 2, 2, 0.01), material),
             {}};
  d.x = d.body.rest_positions();
  viscera::testing::jiggle(d.x, 0.002, seed);
  return d;
}

double total_energy(const viscera::testing::TeschnerBody& body, const std::vector<Vec3>& x) {
  return distance_energy(x, body.distance_terms()) + area_energy(x, body.area_terms()) +
         volume_energy(x, body.volume_terms());
}

std::vector<Vec3> forces_at(const viscera::testing::TeschnerBody& body, const std::vector<Vec3>& x,
                            const std::vector<Vec3>& v) {
  std::vector<Vec3> f(x.size(), Vec3::Zero());
  add_distance_forces(x, v, body.distance_terms(), f);
  add_area_forces(x, body.area_terms(), f);
  add_volume_forces(x, body.volume_terms(), f);
  return f;
}

TEST(TeschnerEnergies, forces_are_the_negative_energy_gradient) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    Deformed d = deformed_block(seed);
    const std::vector<Vec3> zero(d.x.size(), Vec3::Zero());
    const auto f = forces_at(d.body, d.x, zero);
    const double h = 1e-7;
    double largest = 0.0;
    for (const auto& force : f)
      largest = std::max(largest, force.norm());
    for (std::size_t i = 0; i < d.x.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        auto plus = d.x, minus = d.x;
        plus[i][c] += h;
        minus[i][c] -= h;
        const double gradient =
            (total_energy(d.body, plus) - total_energy(d.body, minus)) / (2 * h);
        ASSERT_NEAR(f[i][c], -gradient, 1e-5 * largest) << "node " << i << " axis " << c;
      }
    }
  }
}

TEST(TeschnerEnergies, each_energy_returns_what_its_energy_function_computes) {
  Deformed d = deformed_block(4);
  std::vector<Vec3> f(d.x.size(), Vec3::Zero()), v(d.x.size(), Vec3::Zero());
  EXPECT_DOUBLE_EQ(add_distance_forces(d.x, v, d.body.distance_terms(), f),
                   distance_energy(d.x, d.body.distance_terms()));
  EXPECT_DOUBLE_EQ(add_area_forces(d.x, d.body.area_terms(), f),
                   area_energy(d.x, d.body.area_terms()));
  EXPECT_DOUBLE_EQ(add_volume_forces(d.x, d.body.volume_terms(), f),
                   volume_energy(d.x, d.body.volume_terms()));
  EXPECT_GT(distance_energy(d.x, d.body.distance_terms()), 0.0);
  EXPECT_EQ(distance_energy(d.body.rest_positions(), d.body.distance_terms()), 0.0);
}

TEST(TeschnerEnergies, internal_forces_conserve_linear_and_angular_momentum) {
  Deformed d = deformed_block(5);
  // Random velocities too: the damping forces must also be internal.
  std::vector<Vec3> v = d.x;
  viscera::testing::jiggle(v, 0.5, 77);
  std::vector<Vec3> f(d.x.size(), Vec3::Zero());
  add_distance_forces(d.x, v, d.body.distance_terms(), f);  // damping is zero in the material…
  DistanceTerms damped = d.body.distance_terms();
  for (auto& k : damped.damping)
    k = 0.3;  // …so add damped terms explicitly
  add_distance_forces(d.x, v, damped, f);
  add_area_forces(d.x, d.body.area_terms(), f);
  add_volume_forces(d.x, d.body.volume_terms(), f);
  Vec3 net = Vec3::Zero(), torque = Vec3::Zero();
  double scale = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    net += f[i];
    torque += d.x[i].cross(f[i]);
    scale += f[i].norm();
  }
  EXPECT_LT(net.norm(), 1e-12 * scale);
  EXPECT_LT(torque.norm(), 1e-12 * scale * 0.03);
}

TEST(TeschnerEnergies, damping_opposes_relative_velocity_along_the_edge) {
  DistanceTerms terms{{{0, 1}}, {1.0}, {0.0}, {2.0}};
  const std::vector<Vec3> x = {Vec3::Zero(), Vec3::UnitX()};
  const std::vector<Vec3> v = {Vec3::Zero(), Vec3(3.0, 5.0, 0.0)};  // separating at 3 m/s
  std::vector<Vec3> f(2, Vec3::Zero());
  add_distance_forces(x, v, terms, f);
  EXPECT_NEAR(f[1].x(), -6.0, 1e-12);  // −k_d · Ċ · ∂C/∂p = −2 · 3 · 1
  EXPECT_NEAR(f[1].y(), 0.0, 1e-12);   // motion across the edge is not damped
  EXPECT_NEAR(f[0].x(), 6.0, 1e-12);
}

/// One tet of 1 cm legs; only volume terms unless a test adds others.
core::TetMesh single_tet() {
  core::TetMesh tet;
  tet.nodes = {Vec3::Zero(), Vec3::UnitX() * 0.01, Vec3::UnitY() * 0.01, Vec3::UnitZ() * 0.01};
  tet.tets = {{0, 1, 2, 3}};
  return tet;
}

TEST(TeschnerEnergies, forces_are_the_negative_energy_gradient_on_inverted_tets) {
  // The signed volume of eq. 6 must be differentiated as signed: an inverted tet is where an
  // unsigned |V| (or a sign slip in its gradient) would show.
  core::Material material;
  material.distance_stiffness = 0.0;
  material.volume_stiffness = 10000.0;
  viscera::testing::TeschnerBody body(single_tet(), material);
  for (const double depth : {-0.004, -0.02}) {  // |V| below and above V0
    std::vector<Vec3> x = body.rest_positions();
    x[3] = Vec3(0.002, 0.003, depth);
    ASSERT_LT(core::signed_volume(x[0], x[1], x[2], x[3]), 0.0);
    std::vector<Vec3> f(x.size(), Vec3::Zero());
    add_volume_forces(x, body.volume_terms(), f);
    const double h = 1e-8;
    for (std::size_t i = 0; i < x.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        auto plus = x, minus = x;
        plus[i][c] += h;
        minus[i][c] -= h;
        const double gradient =
            (volume_energy(plus, body.volume_terms()) - volume_energy(minus, body.volume_terms())) /
            (2 * h);
        ASSERT_NEAR(f[i][c], -gradient, 1e-6 * std::max(1.0, std::abs(gradient)))
            << "depth " << depth << " node " << i;
      }
    }
  }
}

TEST(TeschnerEnergies, inverted_tet_is_pushed_back_to_its_orientation) {
  // Damped and with a step ten times below the stability bound, so the tet cannot jump through
  // its degenerate state by overshoot: it must be driven back and settle at +V0. An energy in
  // the unsigned |V| would settle at −V0 instead.
  core::Material material;
  material.distance_stiffness = 0.0;
  material.distance_damping = 20.0;
  material.volume_stiffness = 10000.0;
  for (const double depth : {-0.004, -0.02}) {
    viscera::testing::TeschnerBody body(single_tet(), material);
    const double rest_volume = body.volume_terms().rest_volume[0];
    body.state.positions[3] = Vec3(0.002, 0.002, depth);
    const auto signed_volume = [&] {
      const auto& p = body.state.positions;
      return core::signed_volume(p[0], p[1], p[2], p[3]);
    };
    ASSERT_LT(signed_volume(), 0.0);
    ExplicitVerlet verlet;
    const auto terms = body.terms();
    verlet.topology_changed(body.state, terms);
    const double h = 0.1 * verlet.stable_step();
    for (int s = 0; s < 20000; ++s)
      verlet.step(body.state, terms, {s * h, h, s + 1});
    EXPECT_NEAR(signed_volume(), rest_volume, 0.02 * rest_volume)
        << "apex started at z = " << depth;
  }
}

}  // namespace
}  // namespace viscera::sim
