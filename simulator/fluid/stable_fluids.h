#pragma once
/// One step of the distension flow solver (seed 000 §2.2): Stam's stable fluids (Stam 1999) on
/// the labelled MAC grid — semi-Lagrangian self-advection (first order or MacCormack), implicit
/// viscosity, body forces, pressure projection to a stated divergence — threaded over the cores
/// line by line, bit-identical for any thread count. Stam adds the forces first; here they come
/// just before the projection, so fluid at rest under gravity stays at rest (the pressure takes
/// the whole force) instead of stirring where viscosity would act on the unprojected fall.

#include "simulator/fluid/flow_grid.h"
#include "simulator/fluid/pressure_projection.h"
#include "simulator/fluid/semi_lagrangian.h"
#include "simulator/fluid/viscous_diffusion.h"

namespace viscera::sim::fluid {

struct FlowSettings {
  double viscosity = 1e-6;             ///< ν, m²/s (saline and water at 20 °C: 1.0e-6)
  double time_step = 0.01;             ///< Δt, s
  bool second_order = true;            ///< MacCormack advection instead of first-order back-tracing
  double divergence_tolerance = 1e-4;  ///< largest |∇·u| left by the projection, 1/s
  int max_pressure_iterations = 2000;
  core::Vec3 acceleration = core::Vec3::Zero();  ///< body acceleration, m/s² (none: gravity
                                                 ///< does not drive an incompressible filled
                                                 ///< cavity)
  int threads = 0;                               ///< worker threads; 0 = all cores
};

struct FlowStepReport {
  int diffusion_iterations = 0;
  int pressure_iterations = 0;
  bool converged = false;       ///< the projection reached the stated divergence
  double max_divergence = 0.0;  ///< 1/s, after the step
};

/// The flow solver for repeated steps: keeps the advection's scratch arrays, the viscous step's
/// face lists and the projection's multigrid hierarchy while the grid's labels stay.
class FlowSolver {
 public:
  /// Advances `grid`'s velocity and pressure by settings.time_step. The faces must be up to date
  /// with the cells (FlowGrid::update_faces after relabelling). Throws core::UsageError for a
  /// non-positive step or a negative viscosity.
  FlowStepReport step(FlowGrid& grid, const FlowSettings& settings);

 private:
  VelocityAdvection advection_;
  ViscousDiffusion diffusion_;
  PressureProjector projector_;
};

/// One step with a fresh FlowSolver (the hierarchy is built for this step alone).
FlowStepReport step_flow(FlowGrid& grid, const FlowSettings& settings);

}  // namespace viscera::sim::fluid
