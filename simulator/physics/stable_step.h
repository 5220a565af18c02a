#pragma once
/// The largest stable step of explicit integration from the spectrum of the linearised system
/// instead of a per-node Gershgorin bound. Every Teschner term (seed 000 §3), connection spring
/// and KisMo spring has, at its rest state (C = 0), the Hessian k ∇C ∇Cᵀ: a rank-one matrix. Their
/// sum is the stiffness K (and, with the damping constants, the damping matrix D); power
/// iteration on M^-1/2 K M^-1/2 finds its largest eigenvalue ω²_max, and position Verlet with
/// the backward-difference damping velocity is stable for a mode with ω² and damping rate
/// c = λ(M⁻¹D) while h² ω² + 2 h c < 4. Gershgorin's row sums bound the same eigenvalue from
/// above and may overestimate it several times on a tet mesh, where neighbouring terms pull in
/// different directions; that overestimate is what forced needless sub-steps.

#include <span>
#include <vector>

#include "core/math_types.h"

namespace viscera::sim {

/// A symmetric positive semi-definite matrix over point masses, Σ k_t g_t g_tᵀ + diag(d_n) ⊗ I,
/// stored as its rank-one terms. Nodes are numbered globally (body offset + node).
class RankOneSystem {
 public:
  /// `nodes` point masses, no terms.
  explicit RankOneSystem(std::size_t nodes = 0) : diagonal_(nodes, 0.0) {}

  std::size_t node_count() const { return diagonal_.size(); }
  std::size_t term_count() const { return coefficient_.size(); }

  /// Adds k g gᵀ with the gradient g given per node (g_a at node nodes[a]); k ≥ 0 (N/m for
  /// stiffness with a dimensionless gradient per metre, or N·s/m for damping).
  void add_term(std::span<const int> nodes, std::span<const core::Vec3> gradient, double k);
  /// Adds k·I (3×3) at `node`: a stiffness acting in every direction (contacts, instruments).
  void add_diagonal(int node, double k) { diagonal_[static_cast<std::size_t>(node)] += k; }

  /// y = A x for x, y of node_count() entries.
  void multiply(std::span<const core::Vec3> x, std::span<core::Vec3> y) const;

 private:
  std::vector<std::size_t>
      first_;  ///< per term: offset into nodes_ and gradients_; one past the end last
  std::vector<int> nodes_;
  std::vector<core::Vec3> gradients_;
  std::vector<double> coefficient_;
  std::vector<double> diagonal_;
};

/// Largest eigenvalue of M⁻¹A (the generalised problem A v = λ M v) in 1/s² for stiffness or
/// 1/s for damping, by power iteration on the symmetric M^-1/2 A M^-1/2 from a fixed
/// pseudo-random start (so the result is deterministic). Nodes with zero inverse mass are fixed
/// and drop out. Iterates until the Rayleigh quotient grows by less than `tolerance`
/// (relative) over 20 iterations, or `max_iterations`. The quotient approaches λ_max from
/// below; callers keep a safety factor.
double largest_eigenvalue(const RankOneSystem& a, std::span<const double> inverse_mass,
                          int max_iterations = 600, double tolerance = 1e-5);

/// Largest step in s for which position Verlet with backward-difference velocities keeps a
/// mode of angular frequency² `omega_squared` (1/s²) and damping rate `damping_rate` (1/s, the
/// eigenvalue of M⁻¹D) bounded: the root of h² ω² + 2 h c = 4, i.e. 4 / (c + √(c² + 4 ω²)).
/// Infinite when both are zero.
double verlet_stable_step(double omega_squared, double damping_rate);

}  // namespace viscera::sim
