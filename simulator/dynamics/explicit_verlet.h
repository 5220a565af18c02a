#pragma once
/// Explicit integration, the reference (seed 000 §3): position Verlet in its velocity form
/// (symplectic Euler: v += h M⁻¹ f(x, v), x += h v, identical to x' = 2x − x⁻ + h² a with the
/// backward-difference velocity). The step is split into equal sub-steps below the spectral
/// stable step: the largest eigenvalues ω² of M⁻¹K and c of M⁻¹D (power iteration on the
/// terms' Hessians and damping matrices at rest, plus the worst-case stiffness contact-like
/// terms may add on their nodes), h² ω² + 2 h c < 4, times kStableStepSafety.
///
/// Multi-rate sub-steps (sub-cycling; Belytschko & Mullen 1978 for the idea in explicit
/// dynamics): the bodies fall into islands — bodies joined by a term's blocks (a connection
/// spring, an attachment) are one island — and each island gets its own stable step from one
/// power iteration run per island. When the islands need different numbers of sub-steps, the
/// step is cut into N fine sub-steps (N the smallest of 1, 2, 3, 4, 6, 8, 12, 16, 24, … not
/// below the most any island needs) and an island that needs n advances every N/d of them (d
/// the smallest divisor of N not below n), its own terms (ForceTerm::body()) evaluated only
/// then, as are terms that act per node (gravity: ForceTerm::acts_per_node), on its nodes.
/// Terms that may touch any body (contact, the proxy, tools) are evaluated at every fine
/// sub-step; a slow island receives their mean over its sub-step — the impulse its
/// partners receive, so momentum exchanged between islands is conserved — at the positions it
/// held during that sub-step (zero-order hold). With one island, or islands that all need the
/// same count, the step is the uniform one above, bit for bit. Decision: islands come from the
/// blocks declared at the topology change; contacts that appear later are global terms,
/// covered by the worst-case stiffness they report for the stable step. A term whose worst case
/// acts only within reach (ForceTerm::worst_case_within_reach: the instrument's proxy) is
/// prepared for the step's first sub-step before the plan, and only the islands whose box
/// meets its reach() are planned with its stiffness; the others with their far stable step.
///
/// Islands sleep (set_sleep_threshold; the deactivation of rigid-body engines, per island):
/// in a multi-rate step, an island none of whose nodes moved more than the threshold (m per
/// step) for kCalmStepsToSleep steps, with no own term that drives() and no impulse from the
/// terms of any body, stops: its velocities are set to zero and neither its terms nor its
/// nodes are stepped. It wakes at the next step when a term of any body put an impulse on one
/// of its nodes (the impulse it received while asleep is then applied whole: momentum is
/// kept), when a term that acts within reach reaches it, on wake() and at a topology change
/// that changes the node count. A re-plan with the same nodes (a stiffness changed, a term
/// added) keeps the sleep of the islands whose nodes it leaves unchanged.
/// Decision: a quiet vein beside a pulsing artery costs nothing until something touches it.

#include <vector>

#include "simulator/dynamics/integrator.h"

namespace viscera::sim {

class BlockSparseMatrix;

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
  /// The same after body `body`'s mesh changed: the islands without it whose bodies kept their
  /// node counts keep their stable sub-steps, sleep and impulses (their nodes shifted with the
  /// bodies before them); the rest is re-planned as topology_changed plans it.
  void body_topology_changed(const SimulationState& state, std::span<ForceTerm* const> terms,
                             int body) override;
  /// A term's coefficients changed in place on body `body` (a grasp, coagulated tissue
  /// stiffening) with the nodes and islands as they were: re-plans that body's island alone —
  /// its stable sub-steps are the bits a whole topology_changed gives it, the others' plans
  /// and sleep stay. Falls back to topology_changed before the first plan, after the node
  /// count changed, or for a body out of range.
  void stiffness_changed(const SimulationState& state, std::span<ForceTerm* const> terms, int body);

  /// Largest stable sub-step in s found at the last topology change (the smallest of the
  /// islands').
  double stable_step() const { return stable_step_; }
  /// The finest sub-steps a step of `h` s is cut into (the fastest island's).
  int substeps(double h) const;
  /// Each island's stable sub-step in s, islands in the order of their lowest body.
  std::vector<double> island_stable_steps() const;

  /// Islands fall asleep once calm (above); 0 (the default) keeps every island awake.
  void set_sleep_threshold(double threshold) { sleep_threshold_ = threshold; }
  static constexpr int kCalmStepsToSleep = 200;
  /// Wakes every island: something outside the terms' view changed.
  void wake();
  /// Wakes the island of body `body` (every island for a body out of range).
  void wake_body(int body);
  /// How many islands sleep now.
  int islands_asleep() const;

 private:
  struct Island {
    std::vector<int> nodes;
    double stable_step = 0.0;      ///< s, with every worst case
    double far_stable_step = 0.0;  ///< s, out of the reach of terms that act within reach
    int calm_steps = 0;
    bool asleep = false;
    void wake() {
      asleep = false;
      calm_steps = 0;
    }
  };
  /// After a multi-rate step of `h` s in `fine` sub-steps: islands that received an impulse
  /// while asleep wake and take it; the awake ones not `touched` by a term of any body count
  /// their calm steps and fall asleep.
  void update_sleep(SimulationState& state, std::span<ForceTerm* const> terms, double h, int fine,
                    const std::vector<char>& touched);
  /// The fine sub-steps of a step and, when the islands step at different rates, each island's
  /// stride in fine sub-steps (empty: every island at every fine sub-step, the uniform step).
  struct Plan {
    int fine = 1;
    std::vector<int> strides;
  };
  Plan plan(const std::vector<int>& need) const;
  /// topology_changed (`changed_body` −1) or body_topology_changed.
  void replan(const SimulationState& state, std::span<ForceTerm* const> terms, int changed_body);
  /// Per island now, the island it was before a change of `changed_body`'s mesh when it is
  /// the same bodies with the same node counts (islands_ and island_of_body_ already the new
  /// ones), else −1.
  std::vector<int> islands_kept(std::span<const BodyNodes> bodies,
                                std::span<const int> island_of_body_before,
                                std::span<const Island> before, int changed_body) const;
  /// Stable sub-steps of the islands `island_of_group` (group g of group_of_node is island
  /// island_of_group[g]) from the assembled matrices; `stiffness` takes the within-reach worst
  /// cases on top. Then the smallest over every island.
  void plan_islands(const SimulationState& state, std::span<ForceTerm* const> terms,
                    BlockSparseMatrix& stiffness, const BlockSparseMatrix& damping,
                    std::span<const int> group_of_node, std::span<const int> island_of_group);
  /// Sub-steps each island needs for a step of `h`, in island order; an island marked in `far`
  /// is planned without the worst case of the terms that act within reach.
  std::vector<int> needed_substeps(double h, std::span<const char> far = {}) const;
  /// Per island, 1 when its nodes' box meets none of the `reaching` terms' reach().
  std::vector<char> islands_out_of_reach(const SimulationState& state,
                                         std::span<ForceTerm* const> reaching) const;
  /// `prepared`: terms already prepared for the first sub-step.
  void step_uniform(SimulationState& state, std::span<ForceTerm* const> terms,
                    const StepContext& context, int substeps, std::span<ForceTerm* const> prepared);
  void step_multirate(SimulationState& state, std::span<ForceTerm* const> terms,
                      const StepContext& context, int fine, const std::vector<int>& strides,
                      std::span<ForceTerm* const> prepared);

  double stable_step_ = 0.0;
  bool ready_ = false;
  std::vector<Island> islands_;
  std::vector<int> island_of_body_;
  std::vector<int> planned_layout_;      ///< per body, its node count at the last plan
  bool every_node_in_an_island_ = true;  ///< else the uniform step (no node left unstepped)
  double sleep_threshold_ = 0.0;
  std::vector<Vec3> forces_, shared_impulse_;
};

/// Largest eigenvalue of M⁻¹A by power iteration on M^-1/2 A M^-1/2 from a fixed start (so
/// deterministic); nodes with inverse mass 0 drop out. In 1/s² for stiffness, 1/s for damping.
double largest_eigenvalue(const BlockSparseMatrix& a, std::span<const double> inverse_mass,
                          int max_iterations = 600, double tolerance = 1e-5);

/// largest_eigenvalue for each group of nodes of a matrix with no block between two groups
/// (independent power iterations sharing one product per iteration): group_of_node[i] in
/// [0, groups). With one group it equals largest_eigenvalue bit for bit.
std::vector<double> largest_eigenvalues(const BlockSparseMatrix& a,
                                        std::span<const double> inverse_mass,
                                        std::span<const int> group_of_node, int groups,
                                        int max_iterations = 600, double tolerance = 1e-5);

}  // namespace viscera::sim
