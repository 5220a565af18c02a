#include "simulator/fluid/air_bubbles.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "simulator/fluid/face_sampler.h"

namespace viscera::sim::fluid {
namespace {

constexpr int kNeighbours[6][3] = {{0, 0, 1},  {0, 0, -1}, {0, 1, 0},
                                   {0, -1, 0}, {1, 0, 0},  {-1, 0, 0}};

}  // namespace

AirBubbles::AirBubbles(const AirBubbleSettings& settings, std::uint64_t seed)
    : settings_(settings), rng_(seed) {
  if (!(settings.min_radius > 0.0) || !(settings.max_radius >= settings.min_radius) ||
      !(settings.inflow_per_bubble > 0.0) || !(settings.liquid_viscosity > 0.0) ||
      settings.burst_count < 0)
    throw core::UsageError(
        "air bubbles need positive radii (the largest at least the smallest), a positive inflow "
        "per bubble and viscosity, and a burst of zero or more");
}

double AirBubbles::rise_speed(double radius) const {
  const double stokes = 2.0 * settings_.density_difference * settings_.gravity * radius * radius /
                        (9.0 * settings_.liquid_viscosity);
  return std::min(stokes, settings_.max_rise_speed);
}

void AirBubbles::add(const core::Vec3& at, const FlowGrid& grid) {
  if (positions_.size() >= settings_.capacity) return;
  const double h = grid.cell_size();
  // Spread over a cell around the inlet, so a burst is a cluster and not one dot.
  const core::Vec3 offset(rng_.uniform(-0.5, 0.5), rng_.uniform(-0.5, 0.5),
                          rng_.uniform(-0.5, 0.5));
  positions_.push_back(at + h * offset);
  radii_.push_back(rng_.uniform(settings_.min_radius, settings_.max_radius));
  clinging_.push_back(0);
  ++admitted_;
}

void AirBubbles::admit(double inflow_rate, double time_step, const core::Vec3& inlet,
                       const FlowGrid& grid) {
  if (!(inflow_rate > 0.0)) {
    idle_ += time_step;
    return;
  }
  if (idle_ >= settings_.pause_before_burst)
    for (int b = 0; b < settings_.burst_count; ++b)
      add(inlet, grid);
  idle_ = 0.0;
  inflow_since_bubble_ += inflow_rate * time_step;
  while (inflow_since_bubble_ >= settings_.inflow_per_bubble) {
    inflow_since_bubble_ -= settings_.inflow_per_bubble;
    add(inlet, grid);
  }
}

void AirBubbles::remove(std::size_t i) {
  positions_.erase(positions_.begin() + static_cast<std::ptrdiff_t>(i));
  radii_.erase(radii_.begin() + static_cast<std::ptrdiff_t>(i));
  clinging_.erase(clinging_.begin() + static_cast<std::ptrdiff_t>(i));
}

bool AirBubbles::free_from_tissue(std::size_t i, const FlowGrid& grid) {
  const CellCoord c = grid.cell_of(positions_[i]);
  for (const auto& e : kNeighbours) {
    const CellCoord n{c.i + e[0], c.j + e[1], c.k + e[2]};
    if (grid.cell_or_solid(n) == FlowCell::Solid) continue;
    positions_[i] = grid.origin() + grid.cell_size() * core::Vec3(n.i + 0.5, n.j + 0.5, n.k + 0.5);
    return true;
  }
  return false;
}

void AirBubbles::advance(const FlowGrid& grid, const core::Vec3& up, double time_step) {
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
    const core::Vec3 rise = rise_speed(radii_[i]) * up;
    double left = time_step;
    bool flushed = false;
    while (left > 0.0) {
      const core::Vec3 carried = flow(positions_[i]);
      const double speed = (carried + rise).norm();
      const double dt = speed > 0.0 ? std::min(left, 0.5 * h / speed) : left;
      left -= dt;
      core::Vec3 next = positions_[i] + dt * (carried + rise);
      clinging_[i] = solid(next) ? 1 : 0;
      if (clinging_[i] != 0) {
        next = positions_[i] + dt * carried;  // held under the wall, sliding with the flow
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
