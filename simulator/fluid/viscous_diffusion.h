#pragma once
/// The implicit viscous step of stable fluids (Stam 1999; seed 000 §2.2): (I − νΔt∇²)u' = u for
/// each velocity component on its active faces, unconditionally stable. No-slip at solid cells:
/// the velocity beside a wall takes the wall's, through a ghost value 2·u_wall − u across it, so
/// a moving lid drags the flow. Solved matrix-free by Jacobi-preconditioned conjugate gradients.

#include "simulator/fluid/flow_grid.h"

namespace viscera::sim::fluid {

struct DiffusionSettings {
  double viscosity = 1e-6;           ///< ν, m²/s (water at 20 °C)
  double time_step = 0.01;           ///< Δt, s
  double relative_tolerance = 1e-8;  ///< ‖r‖ ≤ this · ‖b‖ ends the solve
  int max_iterations = 500;
  int threads = 0;  ///< worker threads; 0 = all cores
};

/// Diffuses every component of `grid`'s active face velocities; returns the CG iterations
/// summed over the components (0 when ν is 0).
int diffuse(FlowGrid& grid, const DiffusionSettings& settings);

}  // namespace viscera::sim::fluid
