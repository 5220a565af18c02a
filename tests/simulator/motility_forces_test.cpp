#include "simulator/dynamics/motility_forces.h"

#include <gtest/gtest.h>

#include <numbers>

#include "core/error.h"
#include "simulator/dynamics/backward_euler.h"
#include "simulator/dynamics/teschner_terms.h"
#include "tests/simulator/authored_term_fixtures.h"
#include "tests/simulator/term_derivative_checks.h"

namespace viscera::sim {
namespace {

core::MotilitySpec peristalsis(double frequency) {
  core::MotilitySpec spec;
  spec.amplitude_mean = 0.002;
  spec.wave_speed = 0.05;
  spec.wave_direction = core::Vec3::UnitX();
  spec.frequency = frequency;
  return spec;
}

/// A 6 × 2 × 2 cm soft block (1 cm cells), its x = 0 face held.
std::shared_ptr<BodyModel> block_in(SimulationState& state) {
  return testing::add_tet_body(state, "bowel", testing::tet_block(6, 2, 2, 0.01),
                               testing::soft_test_material(),
                               [](const core::Vec3& p) { return p.x() < 1e-9; });
}

TEST(MotilityForces, pull_towards_the_moving_rest_shape_with_an_exact_gradient_and_hessian) {
  SimulationState state;
  const auto model = block_in(state);
  MotilityForces motility(model, state, peristalsis(0.5), 7, "peristalsis");
  motility.prepare(state, {0.3, 1e-3, 301});
  // The anchors are the rest positions displaced by OrganMotility at the end of the step.
  for (std::size_t i = 0; i < motility.anchors().size(); ++i)
    EXPECT_TRUE(motility.anchors()[i].isApprox(
        state.rest_positions[i] + motility.motility().displacement(i, 0.301), 1e-12));
  std::vector<core::Vec3> x = state.positions;
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] += core::Vec3(0.001 * std::sin(i), 0.0, 0.0005);
  EXPECT_LT(testing::force_gradient_mismatch(motility, x, 1e-7), 1e-6);
  EXPECT_LT(testing::hessian_force_mismatch(motility, x, 1e-7), 1e-6);
  EXPECT_GE(testing::smallest_projected_eigenvalue(motility, x), 0.0);
  // A spring as stiff as the tissue around a free node, none on held ones.
  std::vector<core::Vec3> f(x.size(), core::Vec3::Zero());
  x = motility.anchors();
  x[0] += core::Vec3(0.001, 0.0, 0.0);  // held (x = 0)
  const std::size_t free_node = x.size() - 1;
  x[free_node] += core::Vec3(0.001, 0.0, 0.0);
  motility.add_forces(x, std::vector<core::Vec3>(x.size(), core::Vec3::Zero()), f);
  EXPECT_EQ(f[0], core::Vec3::Zero());
  EXPECT_EQ(motility.stiffness()[0], 0.0);
  // The far corner is the last corner of the six tets of its cube, each with edges of 1, √2
  // and √3 cm to it and k_D = 20 kPa × V0/6 (V0 = 1 cm³ / 6): k = 6 k_D (1 + ½ + ⅓) / 3 cm².
  const double k_d = 20e3 * (1e-6 / 6.0) / 6.0;
  EXPECT_NEAR(motility.stiffness()[free_node], 6.0 * k_d * (1.0 + 0.5 + 1.0 / 3.0) / 3.0 / 1e-4,
              1e-9);
  EXPECT_NEAR(f[free_node].x(), -motility.stiffness()[free_node] * 0.001, 1e-12);
}

TEST(MotilityForces, the_body_moves_periodically_at_the_motility_frequency) {
  SimulationState state;
  const auto model = block_in(state);
  const double frequency = 0.5;  // Hz
  std::vector<std::unique_ptr<ForceTerm>> owned;
  owned.push_back(std::make_unique<TeschnerDistanceTerm>(model, state));
  owned.push_back(std::make_unique<TeschnerVolumeTerm>(model, state));
  owned.push_back(std::make_unique<MotilityForces>(model, state, peristalsis(frequency), 3, "m"));
  std::vector<ForceTerm*> terms;
  for (auto& t : owned)
    terms.push_back(t.get());
  BackwardEuler integrator;
  integrator.topology_changed(state, terms);
  // The free corner's displacement along its radial motility direction, every 10 ms for 6 s.
  const std::size_t node = state.node_count() - 1;
  const double h = 1e-3;
  std::vector<double> signal;
  for (long long s = 0; s < 6000; ++s) {
    integrator.step(state, terms, {static_cast<double>(s) * h, h, s + 1});
    const core::Vec3 d = state.positions[node] - state.rest_positions[node];
    if ((s + 1) % 10 == 0) signal.push_back(d.y() + d.z());  // radial: the corner at (6, 2, 2) cm
  }
  // Skip the first second (start-up), then the dominant frequency of the signal by its
  // correlation with sine and cosine over a grid of frequencies.
  const double dt = 10 * h;
  double best_frequency = 0.0, best_power = 0.0;
  for (double trial = 0.1; trial <= 2.0 + 1e-9; trial += 0.01) {
    double c = 0.0, s = 0.0;
    for (std::size_t k = 100; k < signal.size(); ++k) {
      const double t = static_cast<double>(k + 1) * dt;
      c += signal[k] * std::cos(2.0 * std::numbers::pi * trial * t);
      s += signal[k] * std::sin(2.0 * std::numbers::pi * trial * t);
    }
    if (c * c + s * s > best_power) {
      best_power = c * c + s * s;
      best_frequency = trial;
    }
  }
  EXPECT_NEAR(best_frequency, frequency, 0.03);
  // And it really moves: a peak-to-peak swing of at least a quarter of the authored amplitude.
  const auto [low, high] = std::minmax_element(signal.begin() + 100, signal.end());
  EXPECT_GT(*high - *low, 0.25 * 0.002);
}

TEST(MotilityForces, names_the_deformation_of_an_unusable_spec) {
  SimulationState state;
  const auto model = block_in(state);
  core::MotilitySpec bad = peristalsis(0.5);
  bad.wave_speed = 0.0;
  try {
    MotilityForces(model, state, bad, 1, "peristalsis");
    FAIL() << "a zero wave speed was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("peristalsis"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace viscera::sim
