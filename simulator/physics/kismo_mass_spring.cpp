#include "simulator/physics/kismo_mass_spring.h"

#include <cmath>

namespace viscera::sim {

std::array<double, 3> spring_coefficients_from_cubic(const std::array<double, 3>& c,
                                                     double cross_section) {
  return {c[0] * cross_section, c[1] * cross_section, c[2] * cross_section};
}

namespace {

/// One pass over the springs: the cubic's pull (and with kDamped the damping element's
/// c (v_j − v_i)·d̂, both along d̂ = d / |d|) into f when kForces, and the springs' energy.
template <bool kDamped, bool kForces>
double spring_pass(std::span<const core::Vec3> x, std::span<const core::Vec3> v,
                   const CubicSprings& springs, std::span<core::Vec3> f) {
  double energy = 0.0;
  for (std::size_t s = 0; s < springs.knots.size(); ++s) {
    const auto [i, j] = springs.knots[s];
    const core::Vec3 d = x[j] - x[i];
    const double length = d.norm();
    if (length <= 0.0) continue;
    const double l0 = springs.rest_length[s];
    const double e = (length - l0) / l0, a = std::abs(e);
    const auto& k = springs.coefficients[s];
    energy += l0 * (k[0] * e * e / 2.0 + k[1] * a * a * a / 3.0 + k[2] * e * e * e * e / 4.0);
    if constexpr (kForces) {
      const double inverse = 1.0 / length;
      double magnitude = k[0] * e + k[1] * e * a + k[2] * e * e * e;
      if constexpr (kDamped) magnitude += springs.damping[s] * (v[j] - v[i]).dot(d) * inverse;
      const core::Vec3 pull = (magnitude * inverse) * d;  // towards each other when stretched
      f[i] += pull;
      f[j] -= pull;
    }
  }
  return energy;
}

}  // namespace

double cubic_spring_energy(std::span<const core::Vec3> x, const CubicSprings& springs) {
  return spring_pass<false, false>(x, {}, springs, {});
}

double add_cubic_spring_forces(std::span<const core::Vec3> x, const CubicSprings& springs,
                               std::span<core::Vec3> f) {
  return spring_pass<false, true>(x, {}, springs, f);
}

void add_spring_damping_forces(std::span<const core::Vec3> x, std::span<const core::Vec3> v,
                               const CubicSprings& springs, std::span<core::Vec3> f) {
  for (std::size_t s = 0; s < springs.damping.size(); ++s) {
    const auto [i, j] = springs.knots[s];
    const core::Vec3 d = x[j] - x[i];
    const double length = d.norm();
    if (length <= 0.0) continue;
    const core::Vec3 unit = d / length;
    const core::Vec3 force = (springs.damping[s] * (v[j] - v[i]).dot(unit)) * unit;
    f[i] += force;
    f[j] -= force;
  }
}

double add_damped_cubic_spring_forces(std::span<const core::Vec3> x, std::span<const core::Vec3> v,
                                      const CubicSprings& springs, std::span<core::Vec3> f) {
  return springs.damping.empty() ? spring_pass<false, true>(x, v, springs, f)
                                 : spring_pass<true, true>(x, v, springs, f);
}

void kismo_step(std::span<core::Vec3> x, std::span<core::Vec3> v, std::span<const core::Vec3> f,
                const KnotParameters& knots, const core::Vec3& g, double h) {
  for (std::size_t i = 0; i < x.size(); ++i) {
    const core::Vec3 acceleration = (f[i] - knots.damping[i] * v[i]) / knots.mass[i] + g;
    for (int axis = 0; axis < 3; ++axis) {
      if (knots.bound[i][axis] == 0) {
        v[i][axis] = 0.0;
        continue;
      }
      v[i][axis] += h * acceleration[axis];  // eq. 2
      x[i][axis] += h * v[i][axis];          // eq. 3, with the new velocity
    }
  }
}

}  // namespace viscera::sim
