#pragma once
/// Position Verlet integration (Verlet 1967; seed 000 §3): one force evaluation per step and
/// second-order accurate positions, x(t+h) = 2 x(t) − x(t−h) + h² F / m.

#include <span>

#include "core/math_types.h"

namespace viscera::sim {

/// Advances every free point by one step of h seconds. Points with inverse_mass 0 are fixed:
/// they keep their position. `previous` receives the positions before the step. Returns false
/// when a new position is not finite (the integration blew up).
bool verlet_step(std::span<core::Vec3> positions, std::span<core::Vec3> previous,
                 std::span<const core::Vec3> forces, std::span<const double> inverse_mass, double h);

/// Velocities (x(t) − x(t−h)) / h in m/s, the estimate the damping forces and the kinetic
/// energy use.
void verlet_velocities(std::span<const core::Vec3> positions, std::span<const core::Vec3> previous,
                       double h, std::span<core::Vec3> velocities);

}  // namespace viscera::sim
