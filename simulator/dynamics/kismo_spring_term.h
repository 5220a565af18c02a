#pragma once
/// KisMo cubic springs with damping elements (Kühnapfel et al.; seed 001 §3.2, eq. 1) on the
/// edges of a mass-spring body, as a force term. Force law and energy are those of
/// physics/kismo_mass_spring.h: f(ε) = k1 ε + k2 ε|ε| + k3 ε³, E = l0 ∫ f dε. Coefficients per
/// spring: with a stress-strain cubic in the tet's material k_n = c_n × the spring's cross
/// section (volume share / l0), else k1 = distance_stiffness × the cross section; damping
/// element distance_damping × share / l0².
///
/// Hessian of one spring on d = x_j − x_i: f'(ε)/l0 d̂d̂ᵀ + f/|d| (I − d̂d̂ᵀ); projected: both
/// eigenvalues clamped at zero. Damping matrix c d̂d̂ᵀ.

#include "simulator/dynamics/body_term.h"
#include "simulator/physics/kismo_mass_spring.h"

namespace viscera::sim {

class KismoSpringTerm : public BodyTerm {
 public:
  KismoSpringTerm(std::shared_ptr<const BodyModel> model, const SimulationState& state);
  std::string name() const override { return "kismo-springs " + model().name; }
  double energy(std::span<const Vec3> x) const override;
  double add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                    std::span<Vec3> f) const override;
  void declare_blocks(BlockPattern&) const override;
  void add_stiffness(std::span<const Vec3> x, double scale, bool project,
                     BlockSparseMatrix&) const override;
  void add_damping(std::span<const Vec3> x, double scale, BlockSparseMatrix&) const override;
  const CubicSprings& springs() const { return springs_; }
  /// Rest lengths may be moved by plasticity (after_step of another term); m.
  CubicSprings& mutable_springs() { return springs_; }

 protected:
  void build(const SimulationState& state, int first) override;
  void shift(int delta) override;

 private:
  CubicSprings springs_;
};

}  // namespace viscera::sim
