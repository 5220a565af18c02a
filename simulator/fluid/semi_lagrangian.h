#pragma once
/// Self-advection of the velocity by semi-Lagrangian back-tracing (Stam 1999; seed 000 §2.2):
/// each active face takes the velocity found where its fluid came from one step earlier, traced
/// straight back along the face's own velocity — unconditionally stable. (A midpoint trace costs
/// three more interpolations per face; with MacCormack's correction the lid-driven cavity meets
/// Ghia's tables as closely without it.) The second-order option is
/// MacCormack's predictor–corrector as Selle et al. 2008 apply it to semi-Lagrangian steps: a
/// forward and a backward trace estimate the first-order error, half of it is corrected, and the
/// result is clamped to the range of the values it was interpolated from.
///
/// The traces run line by line in face-index coordinates: each line's displacements (the whole
/// velocity at its faces times Δt/h, in cells) come first from contiguous loads the compiler
/// vectorises, then the interpolations.

#include <array>
#include <vector>

#include "simulator/fluid/flow_grid.h"

namespace viscera::sim::fluid {

/// The advection for repeated steps: keeps its scratch arrays between steps.
class VelocityAdvection {
 public:
  /// Advects every component of `grid`'s active face velocities through `time_step` s.
  void advect(FlowGrid& grid, double time_step, bool second_order, int threads = 0);

 private:
  std::array<std::vector<double>, 3> advected_;
  std::vector<double> low_, high_, corrected_;
};

/// One advection with fresh scratch arrays.
void advect_velocity(FlowGrid& grid, double time_step, bool second_order, int threads = 0);

}  // namespace viscera::sim::fluid
