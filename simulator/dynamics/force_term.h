#pragma once
/// A force term of the simulation core (SOFA's ForceField: addForce / addDForce / addKToMatrix;
/// PositionBasedDynamics' Constraint). Each term owns the rest data of the elements it acts on,
/// with global node indices into the SimulationState, and gives its potential energy, forces
/// f = −∇E − D v, Hessian blocks (exact, or projected to positive semi-definite per element for
/// implicit solves) and damping matrix D. Integrators only ever see this interface.

#include <span>
#include <string>

#include "core/math_types.h"
#include "simulator/dynamics/block_sparse_matrix.h"
#include "simulator/dynamics/simulation_state.h"

namespace viscera::sim {

/// The step a term is prepared for.
struct StepContext {
  double time = 0.0;   ///< s, at the start of the step
  double h = 1e-3;     ///< s, the step length
  long long step = 0;  ///< index of the step being taken (1-based), for error messages
};

class ForceTerm {
 public:
  virtual ~ForceTerm() = default;
  /// What it is and on which body, e.g. "teschner-volume uterus".
  virtual std::string name() const = 0;
  /// Once per (sub-)step, before forces: contact detection, proxy update, active sets.
  virtual void prepare(const SimulationState&, const StepContext&) {}
  /// Potential energy in J at x.
  virtual double energy(std::span<const Vec3> x) const = 0;
  /// Adds −∇E(x) − D(x) v to f (N); returns E(x) in J.
  virtual double add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                            std::span<Vec3> f) const = 0;
  /// Declares the blocks its Hessian and damping matrix touch (once per topology, and after
  /// prepare() when structure_changed() says so).
  virtual void declare_blocks(BlockPattern&) const = 0;
  /// Adds scale · ∂²E/∂x² at x; per element projected to positive semi-definite when
  /// `project` (implicit solves), exact otherwise (finite-difference tests).
  virtual void add_stiffness(std::span<const Vec3> x, double scale, bool project,
                             BlockSparseMatrix&) const = 0;
  /// Adds scale · D (the damping matrix, ∂f/∂v = −D) at x.
  virtual void add_damping(std::span<const Vec3> /*x*/, double /*scale*/,
                           BlockSparseMatrix&) const {}
  /// True when the last prepare() changed the blocks the term touches (contacts, the proxy's
  /// triangle): the integrator then declares the pattern anew.
  virtual bool structure_changed() const { return false; }
  /// After an accepted step: plasticity moves rest data, tearing records requests.
  virtual void after_step(const SimulationState&) {}
  /// An integrator that divides the step into sub-steps calls after_step() after each of them
  /// when true (the proxy follows the surface as it moves), else once after the whole step
  /// (tearing and plasticity judge the strain of the step, as under the implicit integrator).
  virtual bool after_each_substep() const { return true; }
  /// The topology of `body` changed (its node range may have moved): rebuild rest data and
  /// caches from the state. Terms of other bodies re-read their node offsets.
  virtual void topology_changed(const SimulationState&, int /*body*/) {}
  /// A bound in N/m on the stiffness this term may add to any node later (contacts, the proxy),
  /// for the explicit integrator's stable step; 0 for terms whose Hessian at rest says it all.
  virtual double worst_case_node_stiffness() const { return 0.0; }
  /// Global nodes to which worst_case_node_stiffness() applies (empty: none).
  virtual std::span<const int> worst_case_nodes() const { return {}; }
  /// True when the worst-case stiffness can only act within reach() during a step (the
  /// instrument's proxy: near the tip), not on every node of worst_case_nodes() at once. An
  /// integrator that steps islands at their own rates then plans it only for the islands
  /// within reach.
  virtual bool worst_case_within_reach() const { return false; }
  /// The box (m) the term acts within during this step, once it was prepared for the step's
  /// first sub-step (empty: nowhere).
  virtual core::BoundingBox reach() const { return {}; }
  /// The body whose nodes alone this term touches (its internal energies), or −1 for a term
  /// that may touch any body's nodes (contact, the proxy, gravity, tools). An explicit
  /// integrator that steps bodies at their own rates evaluates a body's own terms only at that
  /// body's sub-steps.
  virtual int body() const { return -1; }
  /// True when the force on each node depends on nothing but that node and the time (gravity):
  /// an explicit integrator that steps bodies at their own rates then applies it with
  /// add_node_forces at each island's own sub-steps instead of at every fine sub-step.
  virtual bool acts_per_node() const { return false; }
  /// add_forces restricted to `nodes` (global indices), for terms that act_per_node(): each of
  /// these nodes receives what add_forces would add to it, bit for bit.
  virtual void add_node_forces(std::span<const int> /*nodes*/, std::span<const Vec3> /*x*/,
                               std::span<const Vec3> /*v*/, std::span<Vec3> /*f*/) const {}
  /// True while the term moves what it acts on from outside the state (a grasper's jaws, a clip
  /// still closing): a world with such a term neither falls asleep nor stays asleep.
  virtual bool drives() const { return false; }
};

}  // namespace viscera::sim
