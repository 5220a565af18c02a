#include "simulator/fluid/suspended_particles.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "simulator/fluid/face_sampler.h"

namespace viscera::sim::fluid {
namespace {

constexpr int kNeighbours[6][3] = {{0, 0, 1},  {0, 0, -1}, {0, 1, 0},
                                   {0, -1, 0}, {1, 0, 0},  {-1, 0, 0}};

}  // namespace

SuspendedParticles::SuspendedParticles(const SuspensionSettings& settings) : settings_(settings) {
  if (!(settings.liquid_viscosity > 0.0) || !(settings.max_drift_speed >= 0.0))
    throw core::UsageError(
        "suspended particles need a positive viscosity and a drift speed cap of zero or more");
}

double SuspendedParticles::drift_speed(double radius) const {
  const double stokes = 2.0 * settings_.density_difference * settings_.gravity * radius * radius /
                        (9.0 * settings_.liquid_viscosity);
  return std::clamp(stokes, -settings_.max_drift_speed, settings_.max_drift_speed);
}

bool SuspendedParticles::add(const core::Vec3& position, double radius) {
  if (positions_.size() >= settings_.capacity) return false;
  positions_.push_back(position);
  radii_.push_back(radius);
  resting_.push_back(0);
  ++admitted_;
  return true;
}

void SuspendedParticles::remove(std::size_t i) {
  positions_.erase(positions_.begin() + static_cast<std::ptrdiff_t>(i));
  radii_.erase(radii_.begin() + static_cast<std::ptrdiff_t>(i));
  resting_.erase(resting_.begin() + static_cast<std::ptrdiff_t>(i));
}

bool SuspendedParticles::free_from_tissue(std::size_t i, const FlowGrid& grid) {
  const CellCoord c = grid.cell_of(positions_[i]);
  for (const auto& e : kNeighbours) {
    const CellCoord n{c.i + e[0], c.j + e[1], c.k + e[2]};
    if (grid.cell_or_solid(n) == FlowCell::Solid) continue;
    positions_[i] = grid.origin() + grid.cell_size() * core::Vec3(n.i + 0.5, n.j + 0.5, n.k + 0.5);
    return true;
  }
  return false;
}

void SuspendedParticles::advance(const FlowGrid& grid, const core::Vec3& up, double time_step) {
  const VelocitySampler flow(grid);
  const double h = grid.cell_size();
  const auto solid = [&](const core::Vec3& p) {
    return grid.cell_or_solid(grid.cell_of(p)) == FlowCell::Solid;
  };
  for (std::size_t i = 0; i < positions_.size();) {
    if (solid(positions_[i]) && !free_from_tissue(i, grid)) {
      remove(i);
      ++lost_;
      continue;
    }
    const core::Vec3 drift = drift_speed(radii_[i]) * up;
    double left = time_step;
    bool flushed = false;
    while (left > 0.0) {
      const core::Vec3 carried = flow(positions_[i]);
      const double speed = (carried + drift).norm();
      const double dt = speed > 0.0 ? std::min(left, 0.5 * h / speed) : left;
      left -= dt;
      core::Vec3 next = positions_[i] + dt * (carried + drift);
      resting_[i] = solid(next) ? 1 : 0;
      if (resting_[i] != 0) {
        next = positions_[i] + dt * carried;  // held against the wall, sliding with the flow
        if (solid(next)) continue;
      }
      positions_[i] = next;
      if (!grid.contains(grid.cell_of(next))) break;
      if (grid.cell_or_solid(grid.cell_of(next)) == FlowCell::Open) {
        flushed = true;
        break;
      }
    }
    if (flushed) {
      remove(i);
      ++flushed_;
    } else if (!grid.contains(grid.cell_of(positions_[i]))) {
      remove(i);
      ++lost_;
    } else {
      ++i;
    }
  }
}

}  // namespace viscera::sim::fluid
