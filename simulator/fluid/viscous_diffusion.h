#pragma once
/// The implicit viscous step of stable fluids (Stam 1999; seed 000 §2.2): (I − νΔt∇²)u' = u for
/// each velocity component on its active faces, unconditionally stable. No-slip at solid cells:
/// the velocity beside a wall takes the wall's, through a ghost value 2·u_wall − u across it, so
/// a moving lid drags the flow. Solved by Jacobi-preconditioned conjugate gradients over a
/// compact list of the active faces and their neighbours, kept while the grid's labels stay
/// (νΔt/h² is small for saline at millimetre cells, so a few iterations do).
///
/// Where νΔt/h² is at most DiffusionSettings::explicit_limit the step is explicit instead:
/// u' = u + νΔt∇²u, one sweep of the same stencil. Forward Euler on this stencil is stable while
/// νΔt/h²·λ_max ≤ 2, and Gershgorin bounds λ_max by 18 (a ghost wall doubles a side's weight),
/// so up to 0.11; below 0.05 the two steps differ by O((νΔt/h²)²) of the velocity — for saline
/// at 1 mm cells and 10 ms, 0.01, a 1e-4 relative difference of the viscous change — and the
/// explicit one costs one sweep instead of a dozen conjugate-gradient iterations.

#include <array>
#include <cstdint>
#include <vector>

#include "simulator/fluid/flow_grid.h"

namespace viscera::sim::fluid {

struct DiffusionSettings {
  double viscosity = 1e-6;           ///< ν, m²/s (water at 20 °C)
  double time_step = 0.01;           ///< Δt, s
  double relative_tolerance = 1e-8;  ///< ‖r‖ ≤ this · ‖b‖ ends the solve
  int max_iterations = 500;
  int threads = 0;  ///< worker threads; 0 = all cores
  /// Largest νΔt/h² stepped explicitly (see above); 0 makes every step implicit.
  double explicit_limit = 0.05;
};

/// The viscous step for repeated use: keeps each component's face lists while the grid's
/// labelling (FlowGrid::labelling) stays.
class ViscousDiffusion {
 public:
  /// Diffuses every component of `grid`'s active face velocities; returns the CG iterations
  /// summed over the components (0 when ν is 0 or the step is explicit).
  int diffuse(FlowGrid& grid, const DiffusionSettings& settings);

 private:
  /// One component's active faces in grid order, as the unknowns 0…m−1 (m: the zero slot).
  struct Component {
    std::vector<int> faces;                        ///< grid face index of each unknown
    std::vector<std::array<int, 6>> next;          ///< neighbouring unknowns, m where none
    std::vector<double> weight;                    ///< Σ neighbour weights of each unknown
    std::vector<int> boundary_start;               ///< per unknown, into `boundary` (size m + 1)
    std::vector<std::pair<int, double>> boundary;  ///< (grid face, factor) of fixed neighbours
  };
  void build(const FlowGrid& grid);
  /// u' = u + α(Σ neighbours + fixed neighbours − weight·u) on one component's unknowns.
  void step_explicitly(const Component& c, std::vector<double>& u, double alpha, int threads);

  std::uint64_t labelling_ = 0;
  std::array<Component, 3> components_;
  std::vector<double> x_, b_, r_, z_, p_, q_, partials_;
};

/// Diffuses once with a fresh ViscousDiffusion.
int diffuse(FlowGrid& grid, const DiffusionSettings& settings);

}  // namespace viscera::sim::fluid
