#pragma once
/// A clip squeezing a tube or vessel shut (seed 001 §4.1, §5.1.2: clips "define constraints for
/// the interacting mass knots"; issue 19 §3). The clip's jaws close along the unit direction d
/// until the crushed walls between them are `closed_gap` m thick: every clipped node i further
/// than δ = closed_gap / 2 from the plane through the clipped nodes' centroid c (normal d) is
/// pulled onto that slab. With s_i = (x_i − c)·d, ψ(s) = sign(s) max(|s| − δ, 0):
///
///   E = ½ k Σ ψ(s_i)²,  c = (1/n) Σ x_m,
///   f_m = −k (ψ_m − ψ̄) d      (Σ f = 0: the clip's own mass is neglected, so it rides with the
///                               tissue and the squeeze conserves momentum),
///   ∂²E/∂x_m∂x_j = k d dᵀ (P A P)_mj,  P = I − 11ᵀ/n, A = diag(|s_i| > δ)  (semi-definite).
///
/// The jaws close over `closing_time` s from `placed_at` (k rises linearly from 0 over it), as a
/// clip applier's handle is squeezed, so the tissue is not struck flat in one step.
/// The clip stays: the term lives until the session ends, and its nodes are found again by
/// their rest positions after a cut (node_reference.h).

#include <vector>

#include "simulator/dynamics/force_term.h"
#include "simulator/dynamics/node_reference.h"

namespace viscera::sim {

class ClipTerm : public ForceTerm {
 public:
  /// Throws core::UsageError for fewer than two nodes, a non-positive stiffness (N/m per node),
  /// a zero direction or a negative closed gap (m).
  ClipTerm(std::vector<NodeReference> nodes, const Vec3& closing_direction, double stiffness,
           const SimulationState& state, double closed_gap = 0.0);

  std::string name() const override { return "clip"; }
  /// Sets the squeeze for the step starting at context.time.
  void prepare(const SimulationState& state, const StepContext& context) override;
  double energy(std::span<const Vec3> x) const override;
  double add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                    std::span<Vec3> f) const override;
  void declare_blocks(BlockPattern& pattern) const override { pattern.add_clique(globals_); }
  void add_stiffness(std::span<const Vec3> x, double scale, bool project,
                     BlockSparseMatrix&) const override;
  void topology_changed(const SimulationState& state, int body) override;
  /// Notes where the squeezed nodes are, so that a later cut finds the squeezed copy of each.
  void after_step(const SimulationState& state) override;
  /// Once per step: cuts come between steps, not between an explicit integrator's sub-steps.
  bool after_each_substep() const override { return false; }
  /// The explicit integrator plans for the closed clip from the start.
  double worst_case_node_stiffness() const override { return stiffness_; }
  std::span<const int> worst_case_nodes() const override { return globals_; }

  /// The jaws start closing at `placed_at` s and are closed `closing_time` s later (0: at once).
  void close_over(double placed_at, double closing_time);
  /// The jaws are still closing.
  bool drives() const override { return current_stiffness_ < stiffness_; }
  const std::vector<NodeReference>& nodes() const { return nodes_; }
  const Vec3& closing_direction() const { return direction_; }
  /// Centroid of the clipped nodes at x, m: where the clip sits.
  Vec3 centre(std::span<const Vec3> x) const;
  /// Extent of the clipped nodes along the closing direction at x, m: the lumen left open.
  double gap(std::span<const Vec3> x) const;

 private:
  std::vector<NodeReference> nodes_;
  std::vector<int> globals_;
  /// s_i − δ clipped: per node ψ(s_i) at x, and their mean.
  std::vector<double> squeeze(std::span<const Vec3> x, double& mean) const;
  Vec3 direction_;
  double stiffness_;
  double current_stiffness_;  ///< N/m, stiffness_ once the jaws are closed
  double half_gap_;
  double placed_at_ = 0.0, closing_time_ = 0.0;
};

}  // namespace viscera::sim
