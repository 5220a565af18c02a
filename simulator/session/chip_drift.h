#pragma once
/// The distension flow's drag on the chips of a resection (issue 17 §3; seed 000 §7, Fig. 6–7:
/// "excised tissue moved against fundus" by the inflow). After each flow step the session turns
/// the flow around every chip into a drag on its nodes (dynamics/fluid_drag.h), so chips drift
/// with the fluid, away from the stump they were cut from, and settle where the flow and the
/// wall hold them.
///
/// Decided where the seed is silent:
/// - A chip is a sphere of its volume, d = 2 (3V / 4π)^⅓, with the drag of a sphere in a
///   viscous flow at moderate Reynolds numbers, F = 3π μ d (1 + 0.15 Re^0.687) (u − v) (Stokes
///   with the Schiller–Naumann correction, valid for Re < 800; mm chips in cm/s flows have
///   Re ≈ 1–100), Re = |u − v| d / ν from the chip's mean velocity v. The force is shared over
///   the chip's nodes by their mass, so it moves the chip without straining it.
/// - u, the fluid around the chip, is the mean of the flow's velocity one cell outside each of
///   its nodes (from the chip's centre outwards): the grid holds the chip itself as solid.
/// - No gravity: the hysteroscopy scene has none (the cavity is loaded by pressure alone), and
///   tissue of 1,060 kg/m³ in saline weighs 6 % of itself — buoyancy is left out with it.

#include <vector>

#include "simulator/dynamics/fluid_drag.h"
#include "simulator/fluid/flow_grid.h"
#include "simulator/session/loop_resection.h"

namespace viscera::sim {

struct ChipDragSettings {
  double fluid_density = 1000.0;      ///< kg/m³, saline
  double kinematic_viscosity = 1e-6;  ///< ν, m²/s (the flow's)
};

/// The drag of the flow in `grid` on every node of every chip, at the state's positions and
/// velocities (global node indices).
std::vector<NodeDrag> chip_drag(const std::vector<Chip>& chips, const SimulationState& state,
                                const fluid::FlowGrid& grid, const ChipDragSettings& settings);

}  // namespace viscera::sim
