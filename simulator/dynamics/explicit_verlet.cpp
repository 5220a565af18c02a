#include "simulator/dynamics/explicit_verlet.h"

#include <cmath>
#include <limits>

#include "simulator/physics/stable_step.h"

namespace viscera::sim {

double largest_eigenvalue(const BlockSparseMatrix& a, std::span<const double> inverse_mass,
                          int max_iterations, double tolerance) {
  const std::size_t n = a.node_count();
  std::vector<double> scale(n);
  for (std::size_t i = 0; i < n; ++i)
    scale[i] = std::sqrt(inverse_mass[i]);
  // A fixed pseudo-random start (a linear congruential sequence): deterministic everywhere.
  std::vector<Vec3> x(n), y(n), scaled(n);
  std::uint64_t seed = 0x9E3779B97F4A7C15ull;
  for (auto& p : x)
    for (int k = 0; k < 3; ++k) {
      seed = seed * 6364136223846793005ull + 1442695040888963407ull;
      p[k] = static_cast<double>(seed >> 11) * 0x1.0p-53 - 0.5;
    }
  double lambda = 0.0, checkpoint = 0.0;
  for (int it = 0; it < max_iterations; ++it) {
    double norm = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      x[i] *= scale[i] > 0.0 ? 1.0 : 0.0;
      norm += x[i].squaredNorm();
    }
    norm = std::sqrt(norm);
    if (!(norm > 0.0)) return 0.0;
    for (std::size_t i = 0; i < n; ++i)
      scaled[i] = x[i] * (scale[i] / norm);
    a.multiply(scaled, y);
    double quotient = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      y[i] *= scale[i];
      quotient += y[i].dot(x[i]) / norm;
    }
    lambda = std::max(lambda, quotient);
    x.swap(y);
    if (it % 20 == 19) {
      if (lambda <= checkpoint * (1.0 + tolerance)) break;
      checkpoint = lambda;
    }
  }
  return lambda;
}

void ExplicitVerlet::topology_changed(const SimulationState& state,
                                      std::span<ForceTerm* const> terms) {
  BlockPattern pattern(state.node_count());
  for (ForceTerm* t : terms)
    t->declare_blocks(pattern);
  BlockSparseMatrix stiffness, damping;
  stiffness.set_pattern(pattern);
  damping.set_structure_of(stiffness);
  // Rest Hessians (positive semi-definite parts) and damping matrices at the current state,
  // plus k·I on every node a contact-like term may press on later.
  for (ForceTerm* t : terms) {
    t->add_stiffness(state.positions, 1.0, true, stiffness);
    t->add_damping(state.positions, 1.0, damping);
    const double k = t->worst_case_node_stiffness();
    if (k > 0.0)
      for (const int node : t->worst_case_nodes())
        stiffness.block(stiffness.diagonal_slot(node)) += k * Mat3::Identity();
  }
  const double omega_squared = largest_eigenvalue(stiffness, state.inverse_masses);
  const double damping_rate = largest_eigenvalue(damping, state.inverse_masses);
  stable_step_ = kStableStepSafety * verlet_stable_step(omega_squared, damping_rate);
  forces_.assign(state.node_count(), Vec3::Zero());
  ready_ = true;
}

StepStatistics ExplicitVerlet::step(SimulationState& state, std::span<ForceTerm* const> terms,
                                    const StepContext& context) {
  if (!ready_ || forces_.size() != state.node_count()) topology_changed(state, terms);
  StepStatistics stats;
  stats.substeps = std::isfinite(stable_step_)
                       ? std::max(1, static_cast<int>(std::ceil(context.h / stable_step_ - 1e-12)))
                       : 1;
  const double h = context.h / stats.substeps;
  const std::size_t n = state.node_count();
  for (int s = 0; s < stats.substeps; ++s) {
    const StepContext sub{context.time + s * h, h, context.step};
    for (ForceTerm* t : terms)
      t->prepare(state, sub);
    std::fill(forces_.begin(), forces_.end(), Vec3::Zero());
    for (ForceTerm* t : terms)
      t->add_forces(state.positions, state.velocities, forces_);
    // Symplectic Euler = position Verlet with the backward-difference velocity.
    for (std::size_t i = 0; i < n; ++i) {
      const double w = state.inverse_masses[i];
      if (w == 0.0) {
        state.velocities[i].setZero();
        continue;
      }
      state.velocities[i] += (h * w) * forces_[i];
      state.positions[i] += h * state.velocities[i];
    }
    state.time += h;
    const bool last = s + 1 == stats.substeps;
    for (ForceTerm* t : terms)
      if (last || t->after_each_substep()) t->after_step(state);
  }
  return stats;
}

}  // namespace viscera::sim
