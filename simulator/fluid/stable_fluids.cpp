#include "simulator/fluid/stable_fluids.h"

#include <cmath>

#include "core/error.h"
#include "simulator/fluid/pressure_projection.h"
#include "simulator/fluid/semi_lagrangian.h"
#include "simulator/fluid/viscous_diffusion.h"

namespace viscera::sim::fluid {

FlowStepReport FlowSolver::step(FlowGrid& grid, const FlowSettings& settings) {
  if (!(settings.time_step > 0.0) || !std::isfinite(settings.time_step))
    throw core::UsageError("the flow's time step must be a positive number of seconds");
  if (!(settings.viscosity >= 0.0) || !std::isfinite(settings.viscosity))
    throw core::UsageError("the flow's viscosity must be zero or positive, in m²/s");
  FlowStepReport report;
  advection_.advect(grid, settings.time_step, settings.second_order, settings.threads);
  DiffusionSettings diffusion;
  diffusion.viscosity = settings.viscosity;
  diffusion.time_step = settings.time_step;
  diffusion.threads = settings.threads;
  report.diffusion_iterations = diffusion_.diffuse(grid, diffusion);
  // Body forces last, just before the projection: a conservative force (gravity in a closed
  // cavity) is then taken up by the pressure whole, and viscosity never acts on it.
  if (!settings.acceleration.isZero()) {
    for (int axis = 0; axis < (grid.planar() ? 2 : 3); ++axis) {
      const auto& states = grid.face_states(axis);
      auto& velocity = grid.velocity(axis);
      for (std::size_t f = 0; f < velocity.size(); ++f)
        if (states[f] == FaceState::Active)
          velocity[f] += settings.time_step * settings.acceleration[axis];
    }
  }
  ProjectionSettings projection;
  projection.time_step = settings.time_step;
  projection.divergence_tolerance = settings.divergence_tolerance;
  projection.max_iterations = settings.max_pressure_iterations;
  projection.threads = settings.threads;
  const ProjectionResult projected = projector_.project(grid, projection);
  report.pressure_iterations = projected.iterations;
  report.converged = projected.converged;
  report.max_divergence = projected.max_divergence;
  return report;
}

FlowStepReport step_flow(FlowGrid& grid, const FlowSettings& settings) {
  FlowSolver solver;
  return solver.step(grid, settings);
}

}  // namespace viscera::sim::fluid
