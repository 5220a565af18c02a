#include "simulator/fluid/artificial_vortices.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace viscera::sim::fluid {

core::Vec3 lamb_oseen_velocity(const Vortex& vortex, double circulation, double core_radius,
                               const core::Vec3& point) {
  const core::Vec3 offset = point - vortex.centre;
  const core::Vec3 radial = offset - offset.dot(vortex.axis) * vortex.axis;
  const double r2 = radial.squaredNorm();
  if (r2 < 1e-24) return core::Vec3::Zero();
  // |v| = Γ/(2πr)·(1 − e^{−r²/r_c²}) along axis × r̂; as a vector, Γ/(2π r²)·(…)·(axis × r).
  const double factor = circulation / (2.0 * std::numbers::pi * r2) *
                        (1.0 - std::exp(-r2 / (core_radius * core_radius)));
  return factor * vortex.axis.cross(radial);
}

ArtificialVortices::ArtificialVortices(const VortexSettings& settings, std::uint64_t seed)
    : settings_(settings), rng_(seed) {}

double ArtificialVortices::strength(const Vortex& vortex) const {
  return vortex.circulation * std::max(0.0, 1.0 - vortex.age / settings_.lifetime);
}

void ArtificialVortices::advance(const FlowGrid& grid, double inflow, double time_step) {
  for (auto& vortex : vortices_) {
    vortex.age += time_step;
    vortex.centre += time_step * grid.velocity_at(vortex.centre);
  }
  std::erase_if(vortices_, [&](const Vortex& v) { return v.age >= settings_.lifetime; });
  const double excess = inflow - settings_.threshold_flow;
  const int wanted =
      excess > 0.0
          ? std::min(settings_.max_count, 1 + static_cast<int>(excess / settings_.flow_per_vortex))
          : 0;
  std::vector<int> fluid;
  if (static_cast<int>(vortices_.size()) < wanted) {
    for (int c = 0; c < grid.cell_count(); ++c) {
      const int i = c % grid.nx(), j = (c / grid.nx()) % grid.ny(), k = c / (grid.nx() * grid.ny());
      if (grid.cell(i, j, k) == FlowCell::Fluid) fluid.push_back(c);
    }
  }
  while (static_cast<int>(vortices_.size()) < wanted && !fluid.empty()) {
    const int c = fluid[static_cast<std::size_t>(
        rng_.uniform_int(0, static_cast<std::int64_t>(fluid.size()) - 1))];
    const int i = c % grid.nx(), j = (c / grid.nx()) % grid.ny(), k = c / (grid.nx() * grid.ny());
    Vortex vortex;
    vortex.centre = grid.origin() + grid.cell_size() * core::Vec3(i + 0.5, j + 0.5, k + 0.5);
    // A uniform direction: normalised Gaussian-free draw by rejection from the unit ball.
    core::Vec3 axis;
    do {
      axis = core::Vec3(rng_.uniform(-1.0, 1.0), rng_.uniform(-1.0, 1.0), rng_.uniform(-1.0, 1.0));
    } while (axis.squaredNorm() > 1.0 || axis.squaredNorm() < 1e-6);
    vortex.axis = grid.planar() ? core::Vec3::UnitZ() : axis.normalized();
    vortex.circulation = settings_.circulation_per_flow * inflow;
    vortices_.push_back(vortex);
  }
}

core::Vec3 ArtificialVortices::velocity(const core::Vec3& point) const {
  core::Vec3 sum = core::Vec3::Zero();
  for (const auto& vortex : vortices_)
    sum += lamb_oseen_velocity(vortex, strength(vortex), settings_.core_radius, point);
  return sum;
}

}  // namespace viscera::sim::fluid
