#pragma once
/// The projection step of stable fluids (Stam 1999; seed 000 §2.2): the velocity is made
/// divergence-free by subtracting Δt∇p, with p from the Poisson equation ∇²p = ∇·u/Δt on the
/// fluid cells — Neumann at solid cells (their faces keep the solid's velocity), Dirichlet p = 0
/// at open cells (outflows). Solved by multigrid-preconditioned conjugate gradients
/// (multigrid_poisson.h), warm-started from the last step's pressure, until the largest
/// divergence left is below a stated residual.

#include <cstdint>
#include <memory>
#include <vector>

#include "simulator/fluid/flow_grid.h"
#include "simulator/fluid/multigrid_poisson.h"

namespace viscera::sim::fluid {

struct ProjectionSettings {
  double time_step = 0.01;             ///< Δt, s
  double divergence_tolerance = 1e-6;  ///< largest |∇·u| left in a fluid cell, 1/s
  int max_iterations = 2000;           ///< CG iterations before giving up (reported)
  int threads = 0;                     ///< worker threads; 0 = all cores
};

struct ProjectionResult {
  int iterations = 0;
  double max_divergence = 0.0;  ///< 1/s, after the projection
  bool converged = false;
};

/// The projection for repeated steps: keeps the multigrid hierarchy of a grid's labelling and
/// rebuilds it when the labels change (FlowGrid::labelling).
class PressureProjector {
 public:
  /// Projects `grid`'s active face velocities onto divergence-free fields and stores the
  /// kinematic pressure (m²/s²) in grid.pressure(). Without any open cell the pressure is
  /// defined up to a constant: the mean of the right-hand side is removed (a net inflow with no
  /// outflow cannot be made divergence-free; what is left is reported in max_divergence).
  ProjectionResult project(FlowGrid& grid, const ProjectionSettings& settings);

 private:
  std::unique_ptr<MultigridPoisson> solver_;
  std::uint64_t labelling_ = 0;
  std::vector<double> rhs_;
};

/// One projection with a fresh PressureProjector.
ProjectionResult project(FlowGrid& grid, const ProjectionSettings& settings);

}  // namespace viscera::sim::fluid
