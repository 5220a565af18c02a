#include "simulator/physics/teschner_energies.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "simulator/dynamics/backward_euler.h"
#include "simulator/dynamics/gravity_term.h"
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

TEST(TeschnerEnergies, forces_are_the_negative_energy_gradient_inside_the_collapse_barrier) {
  // J = V/V0 below the barrier's start: eq. 6 and the barrier together, still a gradient.
  core::Material material;
  material.distance_stiffness = 0.0;
  material.volume_stiffness = 10000.0;
  viscera::testing::TeschnerBody body(single_tet(), material);
  for (const double depth : {0.0015, 0.0005}) {  // J = 0.15 and 0.05 (apex height / 1 cm)
    std::vector<Vec3> x = body.rest_positions();
    x[3] = Vec3(0.002, 0.003, depth);
    ASSERT_LT(core::signed_volume(x[0], x[1], x[2], x[3]),
              kCollapseBarrierStart * body.volume_terms().rest_volume[0]);
    std::vector<Vec3> f(x.size(), Vec3::Zero());
    add_volume_forces(x, body.volume_terms(), f);
    const double h = 1e-9;
    for (std::size_t i = 0; i < x.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        auto plus = x, minus = x;
        plus[i][c] += h;
        minus[i][c] -= h;
        const double gradient =
            (volume_energy(plus, body.volume_terms()) - volume_energy(minus, body.volume_terms())) /
            (2 * h);
        ASSERT_NEAR(f[i][c], -gradient, 1e-5 * std::max(1.0, std::abs(gradient)))
            << "depth " << depth << " node " << i;
      }
    }
  }
  // Zero and negative volume are out of reach: infinite energy, and a force pushing the apex
  // back up (+z) out of the base plane.
  for (const double depth : {0.0, -0.004}) {
    std::vector<Vec3> x = body.rest_positions();
    x[3] = Vec3(0.002, 0.003, depth);
    EXPECT_TRUE(std::isinf(volume_energy(x, body.volume_terms()))) << depth;
    std::vector<Vec3> f(x.size(), Vec3::Zero());
    add_volume_forces(x, body.volume_terms(), f);
    EXPECT_GT(f[3].z(), 0.0) << depth;
  }
}

TEST(TeschnerEnergies, collapse_barrier_is_continuous_convex_and_unbounded) {
  const double start = kCollapseBarrierStart;
  EXPECT_EQ(collapse_barrier(start).value, 0.0);
  EXPECT_EQ(collapse_barrier(1.0).first, 0.0);
  // C² continuity at Ĵ, derivatives by finite differences inside, convexity, growth at 0⁺.
  EXPECT_NEAR(collapse_barrier(start - 1e-7).first, 0.0, 1e-6);
  EXPECT_NEAR(collapse_barrier(start - 1e-7).second, 0.0, 1e-5);
  for (const double j : {0.01, 0.05, 0.1, 0.19}) {
    const double h = 1e-7;
    EXPECT_NEAR(collapse_barrier(j).first,
                (collapse_barrier(j + h).value - collapse_barrier(j - h).value) / (2 * h), 1e-5);
    EXPECT_NEAR(collapse_barrier(j).second,
                (collapse_barrier(j + h).first - collapse_barrier(j - h).first) / (2 * h), 1e-3);
    EXPECT_GT(collapse_barrier(j).second, 0.0);
    EXPECT_LT(collapse_barrier(j).first, 0.0);
  }
  EXPECT_GT(-collapse_barrier(1e-6).first, 1e3 * -collapse_barrier(0.1).first);
  EXPECT_TRUE(std::isinf(collapse_barrier(0.0).value));
}

TEST(TeschnerEnergies, a_load_past_what_eq6_can_hold_leaves_the_tet_at_its_barrier_equilibrium) {
  // The base of a 1 cm tet is held, its apex pressed down with F. Eq. 6 alone holds the apex
  // with at most k_V V0 ∂J/∂z = k_V · (base area)/3 = 10 kPa · 0.5 cm² / 3 ≈ 0.167 N at V = 0;
  // F = 1 N and 10 N would turn it inside out. With the barrier the apex stops where
  // k_V V0 (C + b′(J)) ∂J/∂z = −F (J = z / 1 cm), above the base.
  core::Material material;
  material.distance_stiffness = 0.0;
  material.distance_damping = 5.0;
  material.volume_stiffness = 10000.0;
  core::TetMesh mesh = single_tet();
  mesh.fixed = {1, 1, 1, 0};
  for (const double load : {1.0, 10.0}) {
    viscera::testing::TeschnerBody body(mesh, material);
    const double v0 = body.volume_terms().rest_volume[0];
    const double hold = material.volume_stiffness * (0.01 * 0.01 / 2.0) / 3.0;  // N
    ASSERT_GT(load, 5.0 * hold);
    GravityTerm weight(Vec3(0.0, 0.0, -load / body.state.masses[3]), body.state);
    std::vector<ForceTerm*> terms = body.terms();
    terms.push_back(&weight);
    BackwardEuler integrator;
    integrator.topology_changed(body.state, terms);
    double lowest = 1.0;
    for (int s = 0; s < 3000; ++s) {
      integrator.step(body.state, terms, {s * 1e-3, 1e-3, s + 1});
      lowest = std::min(lowest, body.state.positions[3].z() / 0.01);
    }
    EXPECT_GT(lowest, 0.0) << load;
    // The equilibrium J by bisection on the balance above (∂J/∂z = 100 /m).
    const double k = material.volume_stiffness * v0;
    const auto balance = [&](double j) {
      return k * (j - 1.0 + collapse_barrier(j).first) * 100.0 + load;
    };
    double lo = 1e-9, hi = 1.0;
    for (int i = 0; i < 200; ++i)
      (balance(0.5 * (lo + hi)) < 0.0 ? lo : hi) = 0.5 * (lo + hi);
    EXPECT_NEAR(body.state.positions[3].z() / 0.01, 0.5 * (lo + hi), 1e-3 * 0.5 * (lo + hi) + 1e-6)
        << load;
  }
}

}  // namespace
}  // namespace viscera::sim
