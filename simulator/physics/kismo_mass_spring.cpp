#include "simulator/physics/kismo_mass_spring.h"

#include <algorithm>
#include <cmath>

#include "simulator/physics/spring_pulls.h"

namespace viscera::sim {

std::array<double, 3> spring_coefficients_from_cubic(const std::array<double, 3>& c,
                                                     double cross_section) {
  return {c[0] * cross_section, c[1] * cross_section, c[2] * cross_section};
}

namespace {

/// Springs computed per chunk before their forces are added: the chunk's springs are
/// independent of each other, so their square roots and divisions overlap (or go four wide).
constexpr std::size_t kChunk = 256;

/// Adds the springs' pulls to f when kForces and returns their energy. The pulls of a chunk
/// are computed first, then added in spring order; a run of springs sharing their first knot
/// adds into a register instead of memory (nothing else writes that knot during the run: a
/// spring's knots differ), so every knot receives the same sums in the same order as a
/// one-pass loop.
template <bool kForces>
double spring_pass(std::span<const core::Vec3> x, std::span<const core::Vec3> v,
                   const CubicSprings& springs, bool damped, std::span<core::Vec3> f) {
  std::array<SpringPull, kChunk> pulls;
  double energy = 0.0;
  const std::size_t count = springs.knots.size();
  for (std::size_t begin = 0; begin < count; begin += kChunk) {
    const std::size_t end = std::min(count, begin + kChunk);
    compute_spring_pulls(x, v, springs, damped, begin, end, pulls.data());
    int held = -1;  // the knot whose force is in `sum`
    core::Vec3 sum = core::Vec3::Zero();
    for (std::size_t s = begin; s < end; ++s) {
      const SpringPull& p = pulls[s - begin];
      if (p.energy < 0.0) continue;
      energy += p.energy;
      if constexpr (kForces) {
        const auto [i, j] = springs.knots[s];
        const core::Vec3 pull(p.x, p.y, p.z);
        if (i != held) {
          if (held >= 0) f[held] = sum;
          held = i;
          sum = f[i];
        }
        sum += pull;
        f[j] -= pull;
      }
    }
    if (held >= 0) f[held] = sum;
  }
  return energy;
}

}  // namespace

double cubic_spring_energy(std::span<const core::Vec3> x, const CubicSprings& springs) {
  return spring_pass<false>(x, {}, springs, false, {});
}

double add_cubic_spring_forces(std::span<const core::Vec3> x, const CubicSprings& springs,
                               std::span<core::Vec3> f) {
  return spring_pass<true>(x, {}, springs, false, f);
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
  return spring_pass<true>(x, v, springs, !springs.damping.empty(), f);
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
