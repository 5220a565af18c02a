#include "simulator/fluid/jet_impact.h"

#include <algorithm>

namespace viscera::sim::fluid {

core::Vec3 rebound_velocity(const core::Vec3& v_old, const core::Vec3& normal, double elasticity,
                            double friction) {
  const core::Vec3 v_normal = v_old.dot(normal) * normal;
  const core::Vec3 v_tangent = v_old - v_normal;
  return (1.0 - friction) * v_tangent - elasticity * v_normal;
}

core::Vec3 impact_force(double mass, double k, const core::Vec3& v_old, const core::Vec3& v_new) {
  const double speed = v_old.norm();
  if (speed == 0.0) return core::Vec3::Zero();
  const double lost = std::max(0.0, v_old.squaredNorm() - v_new.squaredNorm());
  return mass * k * lost / speed * v_old;
}

}  // namespace viscera::sim::fluid
