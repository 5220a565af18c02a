#include "simulator/session/chip_drift.h"

#include <cmath>
#include <numbers>

namespace viscera::sim {

std::vector<NodeDrag> chip_drag(const std::vector<Chip>& chips, const SimulationState& state,
                                const fluid::FlowGrid& grid, const ChipDragSettings& settings) {
  std::vector<NodeDrag> drag;
  const double mu = settings.fluid_density * settings.kinematic_viscosity;
  for (const Chip& chip : chips) {
    const int first = state.body(chip.body).first;
    double mass = 0.0;
    Vec3 centre = Vec3::Zero(), velocity = Vec3::Zero();
    for (const int local : chip.nodes) {
      const auto n = static_cast<std::size_t>(first + local);
      mass += state.masses[n];
      centre += state.masses[n] * state.positions[n];
      velocity += state.masses[n] * state.velocities[n];
    }
    if (!(mass > 0.0) || chip.nodes.empty()) continue;
    centre /= mass;
    velocity /= mass;
    Vec3 fluid = Vec3::Zero();
    for (const int local : chip.nodes) {
      const Vec3& x = state.positions[static_cast<std::size_t>(first + local)];
      const Vec3 out = x - centre;
      const double length = out.norm();
      fluid += grid.velocity_at(length > 0.0 ? Vec3(x + grid.cell_size() / length * out) : x);
    }
    fluid /= static_cast<double>(chip.nodes.size());
    const double diameter = 2.0 * std::cbrt(3.0 * chip.rest_volume / (4.0 * std::numbers::pi));
    const double reynolds = (fluid - velocity).norm() * diameter / settings.kinematic_viscosity;
    const double coefficient =
        3.0 * std::numbers::pi * mu * diameter * (1.0 + 0.15 * std::pow(reynolds, 0.687));
    for (const int local : chip.nodes) {
      const int n = first + local;
      drag.push_back({n, coefficient * state.masses[static_cast<std::size_t>(n)] / mass, fluid});
    }
  }
  return drag;
}

}  // namespace viscera::sim
