#pragma once
/// The hydrometra at run time (seed 000 §2.1: "the precomputed deformation states are loaded
/// into the simulator and piecewise linearly interpolated in real time according to the applied
/// fluid pressures"), blended with the dynamic deformation as a term of the core.
///
/// Each step the session hands the distension balance's pressure P (set_pressure); prepare()
/// interpolates the stored states (core/scenario/hydrometra_states.h) to the distended shape
/// X + u(P) and the term acts on every free node i of the organ with
///   f_i = −k_i (x_i − X_i − u_i(P)) + b_i(P),
///   E   = Σ ½ k_i |x_i − X_i − u_i(P)|² − b(P)·x,
/// where b(P) is the cavity pressure load of dynamics/cavity_pressure.h taken on the distended
/// shape itself (at P clamped to the states' range, like the shape). The blend, decided: at a
/// stored state the organ's own Teschner forces at X + u_k are exactly −b (that is what the sweep
/// solved), so without an instrument the wall's equilibrium IS the interpolated shape; the spring,
/// as stiff as `kStiffnessFactor` × the tissue around the node (⅓ Σ k_D/D0² over its edges,
/// node_distance_stiffness in body_model.h, as MotilityForces), carries a pressure change out
/// within a few steps — the "almost instantaneous response" the seed pre-computes — while the
/// instrument, contacts and the wall's elasticity still deform it about that shape. At 0 Pa the
/// target is the rest shape and b = 0, so the term only adds that spring toward rest. The Hessian
/// is k_i I (PSD: the implicit solver stays stable). Held nodes get nothing.

#include <memory>

#include "core/scenario/hydrometra_states.h"
#include "simulator/dynamics/body_term.h"
#include "simulator/dynamics/cavity_pressure.h"

namespace viscera::sim {

class HydrometraForces : public BodyTerm {
 public:
  /// Spring stiffness as a multiple of the node's local distance stiffness.
  static constexpr double kStiffnessFactor = 0.25;

  /// The states of `object` (its hydrometra, the cavity of its surface) on the body of `model`.
  /// Throws core::InputError when the states do not fit the body or the object marks no cavity.
  HydrometraForces(std::shared_ptr<const BodyModel> model, const SimulationState& state,
                   const core::SceneObject& object);

  std::string name() const override { return "hydrometra " + model().name; }
  /// The cavity pressure, Pa, for the next prepare(). Returns an upper bound in m on how far the
  /// target shape has moved since the pressure the term last prepared with (for waking a
  /// sleeping world).
  double set_pressure(double pressure);
  double pressure() const { return pressure_; }
  /// The pressure of the current targets and loads (the last prepare()), Pa.
  double prepared_pressure() const { return prepared_pressure_; }
  /// Interpolates the target shape and its pressure load for the step.
  void prepare(const SimulationState& state, const StepContext& context) override;
  double energy(std::span<const Vec3> x) const override;
  double add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                    std::span<Vec3> f) const override;
  void declare_blocks(BlockPattern&) const override {}  // diagonal blocks only
  void add_stiffness(std::span<const Vec3> x, double scale, bool project,
                     BlockSparseMatrix&) const override;

  /// Where the springs pull the body's nodes (body-local order), m.
  const std::vector<Vec3>& targets() const { return targets_; }
  /// The pressure load on the target shape, N per body node.
  const std::vector<Vec3>& loads() const { return loads_; }
  const core::HydrometraStates& states() const { return states_; }

 protected:
  void build(const SimulationState& state, int first) override;
  void shift(int delta) override { first_ += delta; }
  /// `pressure` clamped to the states' range (Pa); NaN gives the first.
  double clamped(double pressure) const;

 private:
  core::HydrometraStates states_;
  CavitySurface cavity_;
  /// The largest nodal displacement change per Pa over all pressure intervals (m/Pa).
  double slope_ = 0.0;
  int first_ = 0;
  double pressure_ = 0.0, prepared_pressure_ = 0.0;
  std::vector<Vec3> rest_, displacement_, targets_, loads_;
  std::vector<double> stiffness_;  ///< N/m per body node, 0 for held nodes
};

}  // namespace viscera::sim
