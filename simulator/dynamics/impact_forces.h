#pragma once
/// Forces from outside the tissue's mechanics that act on knots for one physics step: the
/// pushes of irrigation drops on the knots they hit (seed 001 §4.3, eq. 4: the impact force
/// "on the hit knot" enters the deformation as an external force). The session sets them after
/// a step; the next step applies them, constant over it, and they are cleared when the session
/// sets the next ones (an impulse of F · h per drop).
///
/// E = −Σ f_i · (x_i − x_i⁰), x⁰ the knots' positions when the forces were set, so −∇E = f and
/// the energy is zero where the forces started; no Hessian and no damping. A topology change of
/// any body clears them (the knots' numbers change; a force lasts one step anyway).

#include <utility>
#include <vector>

#include "simulator/dynamics/force_term.h"

namespace viscera::sim {

class ImpactForces : public ForceTerm {
 public:
  std::string name() const override { return "impact forces"; }
  /// Replaces the forces by `forces`: (global node, N) pairs, the same node may come more than
  /// once (the forces add up). Throws core::UsageError for a node outside the state.
  void set(std::vector<std::pair<int, Vec3>> forces, const SimulationState& state);
  void clear() { forces_.clear(), start_.clear(); }
  const std::vector<std::pair<int, Vec3>>& forces() const { return forces_; }
  /// N, the sum of the forces now set.
  Vec3 total() const;

  double energy(std::span<const Vec3> x) const override;
  double add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                    std::span<Vec3> f) const override;
  void declare_blocks(BlockPattern&) const override {}
  void add_stiffness(std::span<const Vec3>, double, bool, BlockSparseMatrix&) const override {}
  void topology_changed(const SimulationState&, int) override { clear(); }

 private:
  std::vector<std::pair<int, Vec3>> forces_;
  std::vector<Vec3> start_;  ///< x⁰ per force
};

}  // namespace viscera::sim
