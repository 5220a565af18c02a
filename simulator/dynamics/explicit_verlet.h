#pragma once
/// Explicit integration, the reference (seed 000 §3): position Verlet in its velocity form
/// (symplectic Euler: v += h M⁻¹ f(x, v), x += h v, identical to x' = 2x − x⁻ + h² a with the
/// backward-difference velocity). The step is split into equal sub-steps below the spectral
/// stable step: the largest eigenvalues ω² of M⁻¹K and c of M⁻¹D (power iteration on the
/// terms' Hessians and damping matrices at rest, plus the worst-case stiffness contact-like
/// terms may add on their nodes), h² ω² + 2 h c < 4, times kStableStepSafety.

#include <vector>

#include "simulator/dynamics/integrator.h"

namespace viscera::sim {

class ExplicitVerlet : public Integrator {
 public:
  /// Fraction of the spectral stable step the sub-steps use (power iteration approaches λ_max
  /// from below; stiffening under large deformation).
  static constexpr double kStableStepSafety = 0.8;

  std::string name() const override { return "explicit-verlet"; }
  StepStatistics step(SimulationState& state, std::span<ForceTerm* const> terms,
                      const StepContext& context) override;
  /// Recomputes the stable step (also done on the first step).
  void topology_changed(const SimulationState& state, std::span<ForceTerm* const> terms) override;

  /// Largest stable sub-step in s found at the last topology change.
  double stable_step() const { return stable_step_; }

 private:
  double stable_step_ = 0.0;
  bool ready_ = false;
  std::vector<Vec3> forces_;
};

/// Largest eigenvalue of M⁻¹A by power iteration on M^-1/2 A M^-1/2 from a fixed start (so
/// deterministic); nodes with inverse mass 0 drop out. In 1/s² for stiffness, 1/s for damping.
double largest_eigenvalue(const BlockSparseMatrix& a, std::span<const double> inverse_mass,
                          int max_iterations = 600, double tolerance = 1e-5);

}  // namespace viscera::sim
