#pragma once
/// The jaws of a laparoscopic grasper holding tissue (seed 001 §4.1: "grasping"; issue 19 §3).
/// When the jaws close, the nodes between them are taken with their offsets in the jaw frame;
/// while they stay closed each held node i is pulled towards its place on the jaws,
/// t_i = tip + R·o_i, by a spring of stiffness k:
///
///   E = ½ k Σ |x_i − t_i|²,   f_i = −k (x_i − t_i),   Hessian k I on each held node.
///
/// The hand feels the opposite of what the tissue feels: F = k Σ (x_i − t_i), the tissue's pull
/// on the jaws. A held node whose spring force passes `slip_force` tears out of the jaws
/// (released, and reported by the caller as a tear: the tissue gave way where it was held).
///
/// Decisions where the seed is silent: springs, not kinematic constraints, so the integrators
/// keep one force interface and the hand's force is the springs' sum; no friction between
/// jaw and tissue beyond the springs.

#include <vector>

#include "simulator/dynamics/force_term.h"
#include "simulator/dynamics/node_reference.h"

namespace viscera::sim {

class GraspTerm : public ForceTerm {
 public:
  /// `stiffness` N/m per held node. Throws core::UsageError unless it is positive.
  explicit GraspTerm(double stiffness);

  std::string name() const override { return "grasper"; }
  double energy(std::span<const Vec3> x) const override;
  double add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                    std::span<Vec3> f) const override;
  void declare_blocks(BlockPattern&) const override {}  // diagonal blocks only
  void add_stiffness(std::span<const Vec3> x, double scale, bool project,
                     BlockSparseMatrix&) const override;
  void topology_changed(const SimulationState& state, int body) override;
  /// Notes where the held nodes are, so that a later cut finds the held copy of each.
  void after_step(const SimulationState& state) override;
  /// Once per step: cuts come between steps, not between an explicit integrator's sub-steps.
  bool after_each_substep() const override { return false; }

  /// Closes the jaws on `nodes` with the jaw frame at `tip` (m) and `rotation` (columns: the
  /// frame's axes in world); replaces whatever was held.
  void hold(const SimulationState& state, std::vector<NodeReference> nodes, const Vec3& tip,
            const core::Mat3& rotation);
  /// Opens the jaws.
  void release() { held_.clear(), offsets_.clear(), globals_.clear(); }
  /// Moves the jaws; the held nodes follow from the next step on.
  void move_jaws(const Vec3& tip, const core::Mat3& rotation);

  bool holding() const { return !held_.empty(); }
  /// The jaws move the knots they hold.
  bool drives() const override { return holding(); }
  const std::vector<NodeReference>& held() const { return held_; }
  /// Force of the tissue on the jaws, N, at positions x.
  Vec3 force_on_jaws(std::span<const Vec3> x) const;
  /// The largest spring force on one held node, N.
  double largest_node_force(std::span<const Vec3> x) const;
  /// Drops the held nodes whose spring force exceeds `limit` N; returns how many.
  int tear_out(std::span<const Vec3> x, double limit);

 private:
  Vec3 target(std::size_t k) const { return tip_ + rotation_ * offsets_[k]; }
  void refresh_globals(const SimulationState& state);

  double stiffness_;
  std::vector<NodeReference> held_;
  std::vector<Vec3> offsets_;  ///< m, in the jaw frame
  std::vector<int> globals_;   ///< global index of each held node
  Vec3 tip_ = Vec3::Zero();
  core::Mat3 rotation_ = core::Mat3::Identity();
};

}  // namespace viscera::sim
