#include "simulator/fluid/fluid_pool.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace viscera::sim::fluid {

namespace {
void check_volume(double volume, const char* what) {
  if (!(volume >= 0.0) || !std::isfinite(volume))
    throw core::InputError(std::string("the pool cannot take ") + what + " of " +
                           std::to_string(volume) + " m³: volumes must be finite and ≥ 0");
}
}  // namespace

FluidPool::FluidPool(const core::Vec3& floor, const core::Vec3& down, double area)
    : floor_(floor), area_(area) {
  if (!down.allFinite() || down.norm() == 0.0)
    throw core::InputError("the pool needs the direction of gravity, but it is zero or not finite");
  if (!floor.allFinite()) throw core::InputError("the pool's floor is not a finite point");
  if (!(area > 0.0) || !std::isfinite(area))
    throw core::InputError("the pool's area must be positive (m²), not " + std::to_string(area));
  down_ = down.normalized();
}

void FluidPool::add_water(double volume) {
  check_volume(volume, "water");
  contents_.water += volume;
  received_.water += volume;
}

void FluidPool::add_blood(double volume) {
  check_volume(volume, "blood");
  contents_.blood += volume;
  received_.blood += volume;
}

PoolVolumes FluidPool::remove(double volume) {
  check_volume(volume, "a removal");
  const double total = contents_.total();
  PoolVolumes taken;
  if (total <= 0.0 || volume <= 0.0) return taken;
  if (volume >= total) {
    taken = contents_;
  } else {
    taken.water = contents_.water * (volume / total);
    taken.blood = volume - taken.water;
  }
  contents_.water = std::max(0.0, contents_.water - taken.water);
  contents_.blood = std::max(0.0, contents_.blood - taken.blood);
  suctioned_.water += taken.water;
  suctioned_.blood += taken.blood;
  return taken;
}

PoolVolumes FluidPool::suck(const core::Vec3& tip, const SuctionOptions& suction, double dt) {
  if (depth(tip) < -suction.reach) return {};
  return remove(suction.rate * dt);
}

double FluidPool::depth(const core::Vec3& point) const {
  return (point - floor_).dot(down_) + height();
}

core::Vec3 FluidPool::surface_point(const core::Vec3& point) const {
  return point - depth(point) * down_;
}

double FluidPool::blood_fraction() const {
  const double total = contents_.total();
  return total > 0.0 ? contents_.blood / total : 0.0;
}

}  // namespace viscera::sim::fluid
