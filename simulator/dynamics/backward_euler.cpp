#include "simulator/dynamics/backward_euler.h"

#include <algorithm>
#include <cmath>

namespace viscera::sim {

void BackwardEuler::topology_changed(const SimulationState& state,
                                     std::span<ForceTerm* const> terms) {
  declare(state, terms);
}

void BackwardEuler::declare(const SimulationState& state, std::span<ForceTerm* const> terms) {
  // The pattern keeps its pair list's room from the last declaration (a cut adds a few).
  pattern_.reset(state.node_count());
  pattern_.reserve(declared_pairs_ + declared_pairs_ / 4);
  for (ForceTerm* t : terms)
    t->declare_blocks(pattern_);
  declared_pairs_ = pattern_.pairs().size();
  system_.set_pattern(pattern_);
  damping_.set_structure_of(system_);
  const std::size_t n = state.node_count();
  for (auto* v : {&predicted_, &gradient_, &direction_, &trial_, &forces_, &warm_, &zero_, &cg_r_,
                  &cg_z_, &cg_p_, &cg_q_})
    v->assign(n, Vec3::Zero());
  preconditioner_.assign(n, Mat3::Identity());
  declared_ = true;
}

void BackwardEuler::precondition(const SimulationState& state, std::span<const Vec3> r,
                                 std::span<Vec3> z) const {
  // Block symmetric Gauss–Seidel, z = (D + U)⁻¹ D (D + L)⁻¹ r: a forward sweep solves
  // (D + L) y = r, a backward sweep z_i = y_i − D_i⁻¹ Σ_{j>i} A_ij z_j. Fixed nodes' rows and
  // columns are left out (their z is 0).
  const auto& w = state.inverse_masses;
  const std::size_t n = state.node_count();
  for (std::size_t i = 0; i < n; ++i) {
    if (w[i] == 0.0) {
      z[i].setZero();
      continue;
    }
    Vec3 sum = r[i];
    const int begin = system_.row_begin(static_cast<int>(i));
    const auto columns = system_.row_columns(static_cast<int>(i));
    for (std::size_t k = 0; k < columns.size() && columns[k] < static_cast<int>(i); ++k)
      sum.noalias() -=
          system_.block(begin + static_cast<int>(k)) * z[static_cast<std::size_t>(columns[k])];
    z[i] = preconditioner_[i] * sum;
  }
  for (std::size_t i = n; i-- > 0;) {
    if (w[i] == 0.0) continue;
    Vec3 sum = Vec3::Zero();
    const int begin = system_.row_begin(static_cast<int>(i));
    const auto columns = system_.row_columns(static_cast<int>(i));
    for (std::size_t k = columns.size(); k-- > 0 && columns[k] > static_cast<int>(i);)
      sum.noalias() +=
          system_.block(begin + static_cast<int>(k)) * z[static_cast<std::size_t>(columns[k])];
    z[i] -= preconditioner_[i] * sum;
  }
}

int BackwardEuler::solve(const SimulationState& state, std::span<const Vec3> rhs,
                         std::span<Vec3> solution) {
  // Preconditioned conjugate gradients on the free nodes (fixed nodes masked to zero).
  const std::size_t n = state.node_count();
  const auto& w = state.inverse_masses;
  for (std::size_t i = 0; i < n; ++i) {
    if (w[i] == 0.0) {
      preconditioner_[i].setZero();
      solution[i].setZero();
      continue;
    }
    preconditioner_[i] = system_.block(system_.diagonal_slot(static_cast<int>(i))).inverse();
  }
  system_.multiply(solution, cg_q_);
  double rhs_norm = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    cg_r_[i] = w[i] == 0.0 ? Vec3::Zero() : Vec3(rhs[i] - cg_q_[i]);
    rhs_norm += rhs[i].squaredNorm() * (w[i] == 0.0 ? 0.0 : 1.0);
  }
  precondition(state, cg_r_, cg_z_);
  double rz = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    cg_p_[i] = cg_z_[i];
    rz += cg_r_[i].dot(cg_z_[i]);
  }
  const double target = settings_.cg_tolerance * settings_.cg_tolerance * rhs_norm;
  int it = 0;
  for (; it < settings_.max_cg_iterations; ++it) {
    double rr = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      rr += cg_r_[i].squaredNorm();
    if (rr <= target || rr == 0.0) break;
    system_.multiply(cg_p_, cg_q_);
    double pq = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (w[i] == 0.0) cg_q_[i].setZero();
      pq += cg_p_[i].dot(cg_q_[i]);
    }
    if (!(pq > 0.0)) break;
    const double alpha = rz / pq;
    for (std::size_t i = 0; i < n; ++i) {
      solution[i] += alpha * cg_p_[i];
      cg_r_[i] -= alpha * cg_q_[i];
    }
    precondition(state, cg_r_, cg_z_);
    double rz_next = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      rz_next += cg_r_[i].dot(cg_z_[i]);
    const double beta = rz_next / rz;
    rz = rz_next;
    for (std::size_t i = 0; i < n; ++i)
      cg_p_[i] = cg_z_[i] + beta * cg_p_[i];
  }
  return it;
}

StepStatistics BackwardEuler::step(SimulationState& state, std::span<ForceTerm* const> terms,
                                   const StepContext& context) {
  const double h = context.h;
  const std::size_t n = state.node_count();
  for (ForceTerm* t : terms)
    t->prepare(state, context);
  bool restructure = !declared_ || predicted_.size() != n;
  for (ForceTerm* t : terms)
    restructure = restructure || t->structure_changed();
  if (restructure) declare(state, terms);

  const std::vector<Vec3> start = state.positions;
  const auto& m = state.masses;
  const auto& w = state.inverse_masses;
  for (std::size_t i = 0; i < n; ++i)
    predicted_[i] = w[i] == 0.0 ? start[i] : Vec3(start[i] + h * state.velocities[i]);
  damping_.set_zero();
  for (ForceTerm* t : terms)
    t->add_damping(start, 1.0, damping_);

  // Φ(x) = ½ Σ m |x − x̂|² / h² + E(x) + ½ (x − x0)ᵀ D (x − x0) / h.
  std::vector<Vec3>& moved = cg_q_;  // scratch for D (x − x0), reused before each solve
  const auto phi = [&](std::span<const Vec3> x, double energy) {
    double inertia = 0.0, damping = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      inertia += m[i] * (w[i] == 0.0 ? 0.0 : (x[i] - predicted_[i]).squaredNorm());
      trial_[i] = x[i] - start[i];
    }
    damping_.multiply(trial_, moved);
    for (std::size_t i = 0; i < n; ++i)
      damping += trial_[i].dot(moved[i]);
    return 0.5 * inertia / (h * h) + energy + 0.5 * damping / h;
  };

  // Newton starts at the inertial prediction x̂ unless Φ is infinite there (x + h v would
  // collapse a tet through the volume terms' barrier): then at x, where it is finite.
  std::vector<Vec3> x = predicted_;
  {
    double e = 0.0;
    for (ForceTerm* t : terms)
      e += t->energy(x);
    if (!std::isfinite(e)) x = start;
  }
  StepStatistics stats;
  double first_residual = 0.0;
  for (int newton = 0; newton < settings_.max_newton_iterations; ++newton) {
    std::fill(forces_.begin(), forces_.end(), Vec3::Zero());
    double energy = 0.0;
    for (ForceTerm* t : terms)
      energy += t->add_forces(x, zero_, forces_);
    const double phi_x = phi(x, energy);
    // ∇Φ = M (x − x̂)/h² − f(x) + D (x − x0)/h  (moved holds D (x − x0) from phi()).
    double residual = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      gradient_[i] =
          w[i] == 0.0 ? Vec3::Zero()
                      : Vec3(m[i] * (x[i] - predicted_[i]) / (h * h) - forces_[i] + moved[i] / h);
      residual = std::max(residual, gradient_[i].norm());
    }
    stats.residual = residual;
    if (newton == 0) first_residual = residual;
    if (residual <= settings_.residual_tolerance ||
        (newton > 0 && residual <= settings_.relative_tolerance * first_residual))
      break;
    // (M/h² + D/h + K̃) Δ = −∇Φ.
    system_.set_zero();
    for (ForceTerm* t : terms)
      t->add_stiffness(x, 1.0, true, system_);
    for (std::size_t s = 0; s < system_.block_count(); ++s)
      system_.block(static_cast<int>(s)) += damping_.block(static_cast<int>(s)) / h;
    for (std::size_t i = 0; i < n; ++i) {
      system_.block(system_.diagonal_slot(static_cast<int>(i))) +=
          (m[i] / (h * h)) * Mat3::Identity();
      gradient_[i] = -gradient_[i];
    }
    if (newton == 0)
      direction_ = warm_;
    else
      std::fill(direction_.begin(), direction_.end(), Vec3::Zero());
    stats.linear_iterations += solve(state, gradient_, direction_);
    if (newton == 0) warm_ = direction_;
    ++stats.newton_iterations;
    // Backtracking (Armijo) on Φ along Δ; −gradient_ is ∇Φ now.
    double slope = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      slope -= gradient_[i].dot(direction_[i]);
    if (!(slope < 0.0)) {
      for (std::size_t i = 0; i < n; ++i)
        direction_[i] = gradient_[i] * (w[i] * h * h);
      slope = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        slope -= gradient_[i].dot(direction_[i]);
    }
    // Only a step that lowers Φ is taken: an infinite Φ (a tet collapsed through the volume
    // barrier) or no decrease after 12 halvings keeps x and ends the iterations there.
    double alpha = 1.0;
    bool accepted = false;
    std::vector<Vec3> candidate(n);
    for (int halving = 0; halving < 12 && !accepted; ++halving, alpha *= 0.5) {
      for (std::size_t i = 0; i < n; ++i)
        candidate[i] = x[i] + alpha * direction_[i];
      double e = 0.0;
      for (ForceTerm* t : terms)
        e += t->energy(candidate);
      const double phi_candidate = phi(candidate, e);
      // Φ(x) itself not finite: the input is (a non-finite tool tip); the full step carries it
      // into the state, where the world's check names the body and node.
      accepted = !std::isfinite(phi_x) ||
                 (std::isfinite(phi_candidate) && phi_candidate <= phi_x + 1e-4 * alpha * slope);
    }
    if (!accepted) break;
    x.swap(candidate);
  }
  for (std::size_t i = 0; i < n; ++i) {
    state.velocities[i] = w[i] == 0.0 ? Vec3::Zero() : Vec3((x[i] - start[i]) / h);
    state.positions[i] = x[i];
  }
  state.time += h;
  for (ForceTerm* t : terms)
    t->after_step(state);
  return stats;
}

}  // namespace viscera::sim
