#pragma once
/// Drag of the distension fluid on tissue that floats free in it: the chips a resection cuts
/// off (issue 17 §3; seed 000 §7 and Fig. 6–7, where the inflow carries the chips and pushes
/// them against the fundus). The session sets, per node of a chip, a drag coefficient c (kg/s)
/// and the fluid's velocity u (m/s) around it after each flow step; every physics step until the
/// next applies
///
///     f_i = c_i (u_i − v_i),
///
/// the relative-velocity drag of a body in a flow. The part c_i u_i is a load held over the
/// step, written as the energy E = −Σ c_i u_i · (x_i − x_i⁰) (x⁰ where it was set, so −∇E is
/// the load and E starts at zero); the part −c_i v_i is damping, D = diag(c_i), which the
/// implicit integrator takes into its matrix. No Hessian. A topology change of any body clears
/// the drag (node numbers change; the session sets it again at its next flow step).

#include <vector>

#include "simulator/dynamics/force_term.h"

namespace viscera::sim {

/// The drag on one node: global node index, coefficient in kg/s, fluid velocity in m/s.
struct NodeDrag {
  int node = 0;
  double coefficient = 0.0;
  Vec3 fluid_velocity = Vec3::Zero();
};

class FluidDrag : public ForceTerm {
 public:
  std::string name() const override { return "fluid drag"; }
  /// Replaces the drag by `drag` (one entry per node at most). Throws core::UsageError for a
  /// node outside the state or a coefficient that is negative or not finite.
  void set(std::vector<NodeDrag> drag, const SimulationState& state);
  void clear() { drag_.clear(), start_.clear(); }
  const std::vector<NodeDrag>& drag() const { return drag_; }

  double energy(std::span<const Vec3> x) const override;
  double add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                    std::span<Vec3> f) const override;
  void declare_blocks(BlockPattern&) const override {}  // diagonal blocks only
  void add_stiffness(std::span<const Vec3>, double, bool, BlockSparseMatrix&) const override {}
  void add_damping(std::span<const Vec3> x, double scale, BlockSparseMatrix& matrix) const override;
  void topology_changed(const SimulationState&, int) override { clear(); }

 private:
  std::vector<NodeDrag> drag_;
  std::vector<Vec3> start_;  ///< x⁰ per entry
};

}  // namespace viscera::sim
