#include "simulator/fluid/air_bubbles.h"

#include "core/error.h"

namespace viscera::sim::fluid {
namespace {

SuspensionSettings suspension_of(const AirBubbleSettings& s) {
  return {s.liquid_viscosity, s.density_difference, s.gravity, s.max_rise_speed, s.capacity};
}

}  // namespace

AirBubbles::AirBubbles(const AirBubbleSettings& settings, std::uint64_t seed)
    : settings_(settings), rng_(seed), bubbles_(suspension_of(settings)) {
  if (!(settings.min_radius > 0.0) || !(settings.max_radius >= settings.min_radius) ||
      !(settings.inflow_per_bubble > 0.0) || !(settings.liquid_viscosity > 0.0) ||
      settings.burst_count < 0)
    throw core::UsageError(
        "air bubbles need positive radii (the largest at least the smallest), a positive inflow "
        "per bubble and viscosity, and a burst of zero or more");
}

double AirBubbles::rise_speed(double radius) const {
  return bubbles_.drift_speed(radius);
}

void AirBubbles::add(const core::Vec3& at, const FlowGrid& grid) {
  if (bubbles_.size() >= settings_.capacity) return;
  const double h = grid.cell_size();
  // Spread over a cell around the inlet, so a burst is a cluster and not one dot.
  const core::Vec3 offset(rng_.uniform(-0.5, 0.5), rng_.uniform(-0.5, 0.5),
                          rng_.uniform(-0.5, 0.5));
  const double radius = rng_.uniform(settings_.min_radius, settings_.max_radius);
  bubbles_.add(at + h * offset, radius);
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

void AirBubbles::advance(const FlowGrid& grid, const core::Vec3& up, double time_step) {
  bubbles_.advance(grid, up, time_step);
}

}  // namespace viscera::sim::fluid
