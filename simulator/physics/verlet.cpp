#include "simulator/physics/verlet.h"

#include <cmath>

namespace viscera::sim {

bool verlet_step(std::span<core::Vec3> x, std::span<core::Vec3> previous, std::span<const core::Vec3> forces,
                 std::span<const double> inverse_mass, double h) {
  const double h2 = h * h;
  bool finite = true;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (inverse_mass[i] == 0.0) {
      previous[i] = x[i];
      continue;
    }
    const core::Vec3 next = 2.0 * x[i] - previous[i] + (h2 * inverse_mass[i]) * forces[i];
    previous[i] = x[i];
    x[i] = next;
    finite = finite && std::isfinite(next.x() + next.y() + next.z());
  }
  return finite;
}

void verlet_velocities(std::span<const core::Vec3> x, std::span<const core::Vec3> previous, double h,
                       std::span<core::Vec3> v) {
  const double inverse_h = 1.0 / h;
  for (std::size_t i = 0; i < x.size(); ++i) v[i] = (x[i] - previous[i]) * inverse_h;
}

}  // namespace viscera::sim
