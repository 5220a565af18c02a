#pragma once
/// Integrators behind one interface (PositionBasedDynamics' TimeStep, SOFA's OdeSolver): they
/// advance the SimulationState by one step of h seconds using only the ForceTerm interface.

#include <span>
#include <string>

#include "simulator/dynamics/force_term.h"

namespace viscera::sim {

/// What one step cost.
struct StepStatistics {
  int substeps = 1;
  int newton_iterations = 0;
  int linear_iterations = 0;
  double residual = 0.0;  ///< N, largest nodal force residual left by the implicit solve
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  /// "explicit-verlet" or "backward-euler".
  virtual std::string name() const = 0;
  /// Advances `state` by h seconds: calls prepare() of every term (per sub-step), solves, and
  /// after_step() once the step is accepted (after each sub-step for the terms whose
  /// after_each_substep() says so). `context.step` names the step in errors.
  virtual StepStatistics step(SimulationState& state, std::span<ForceTerm* const> terms,
                              const StepContext& context) = 0;
  /// The node ranges or the terms changed: rebuild the solver structure.
  virtual void topology_changed(const SimulationState&, std::span<ForceTerm* const>) {}
  /// Body `body`'s mesh changed (a cut, a crack) and nothing else: an integrator may keep what
  /// it built for the rest; by default it rebuilds everything.
  virtual void body_topology_changed(const SimulationState& state,
                                     std::span<ForceTerm* const> terms, int /*body*/) {
    topology_changed(state, terms);
  }
};

}  // namespace viscera::sim
