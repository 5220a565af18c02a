#include "simulator/physics/teschner_energies.h"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

namespace viscera::sim {

CollapseBarrier collapse_barrier(double j) {
  constexpr double start = kCollapseBarrierStart;
  if (j >= start) return {};
  CollapseBarrier b;
  if (!(j > 0.0)) {
    b.value = std::numeric_limits<double>::infinity();
    j = start * 1e-3;
  }
  const double d = j - start, log = std::log(j / start);
  if (j > 0.0 && b.value == 0.0) b.value = -d * d * log;
  b.first = -(2.0 * d * log + d * d / j);
  b.second = -(2.0 * log + 4.0 * d / j - d * d / (j * j));
  return b;
}

double add_distance_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                           const DistanceTerms& terms, std::span<Vec3> f) {
  double energy = 0.0;
  for (std::size_t e = 0; e < terms.edges.size(); ++e) {
    const auto [i, j] = terms.edges[e];
    const Vec3 d = x[j] - x[i];
    const double length = d.norm();
    if (length <= 0.0) continue;  // coincident points: the direction is undefined
    // One division per term: ∂C/∂p_j = û / D0 = d / (|d| D0), ∂C/∂p_i = −∂C/∂p_j.
    const double rest = terms.rest_length[e];
    const double inverse = 1.0 / (length * rest);
    const double c = (length - rest) * length * inverse;
    const Vec3 grad_j = d * inverse;
    const double c_dot = grad_j.dot(v[j] - v[i]);
    const double magnitude = -terms.stiffness[e] * c - terms.damping[e] * c_dot;
    f[j] += magnitude * grad_j;
    f[i] -= magnitude * grad_j;
    energy += 0.5 * terms.stiffness[e] * c * c;
  }
  return energy;
}

double add_area_forces(std::span<const Vec3> x, const AreaTerms& terms, std::span<Vec3> f) {
  double energy = 0.0;
  for (std::size_t t = 0; t < terms.triangles.size(); ++t) {
    const auto [a, b, c] = terms.triangles[t];
    const Vec3 n = (x[b] - x[a]).cross(x[c] - x[a]);
    const double twice_area = n.norm();
    if (twice_area <= 0.0) continue;  // degenerate triangle: no defined gradient
    const double rest = terms.rest_area[t];
    const double constraint = (0.5 * twice_area - rest) / rest;
    const Vec3 unit = n / twice_area;
    // ∂A/∂a = ½ n̂ × (c − b), cyclically; ∂C/∂p = ∂A/∂p / A0.
    const double scale = -terms.stiffness[t] * constraint * 0.5 / rest;
    f[a] += scale * unit.cross(x[c] - x[b]);
    f[b] += scale * unit.cross(x[a] - x[c]);
    f[c] += scale * unit.cross(x[b] - x[a]);
    energy += 0.5 * terms.stiffness[t] * constraint * constraint;
  }
  return energy;
}

double add_volume_forces(std::span<const Vec3> x, const VolumeTerms& terms, std::span<Vec3> f) {
  double energy = 0.0;
  for (std::size_t t = 0; t < terms.tets.size(); ++t) {
    const auto [i, j, k, l] = terms.tets[t];
    const Vec3 e1 = x[j] - x[i], e2 = x[k] - x[i], e3 = x[l] - x[i];
    // 6 ∂V/∂p_j = e2 × e3, 6 ∂V/∂p_k = e3 × e1, 6 ∂V/∂p_l = e1 × e2, ∂V/∂p_i = −their sum;
    // the first also gives 6V = e1 · (e2 × e3). One division per tet: C = 6V/(6V0) − 1 and
    // ∂C/∂p = 6 ∂V/∂p / (6V0).
    const Vec3 gj = e2.cross(e3), gk = e3.cross(e1), gl = e1.cross(e2);
    const double inverse_rest6 = 1.0 / (6.0 * terms.rest_volume[t]);
    const double c = e1.dot(gj) * inverse_rest6 - 1.0;
    const CollapseBarrier barrier = collapse_barrier(c + 1.0);
    const double scale = -terms.stiffness[t] * (c + barrier.first) * inverse_rest6;
    f[j] += scale * gj;
    f[k] += scale * gk;
    f[l] += scale * gl;
    f[i] -= scale * (gj + gk + gl);
    energy += terms.stiffness[t] * (0.5 * c * c + barrier.value);
  }
  return energy;
}

double distance_energy(std::span<const Vec3> x, const DistanceTerms& terms) {
  double energy = 0.0;
  for (std::size_t e = 0; e < terms.edges.size(); ++e) {
    const double c = ((x[terms.edges[e][1]] - x[terms.edges[e][0]]).norm() - terms.rest_length[e]) /
                     terms.rest_length[e];
    energy += 0.5 * terms.stiffness[e] * c * c;
  }
  return energy;
}

double area_energy(std::span<const Vec3> x, const AreaTerms& terms) {
  double energy = 0.0;
  for (std::size_t t = 0; t < terms.triangles.size(); ++t) {
    const auto [a, b, c] = terms.triangles[t];
    const double area = 0.5 * (x[b] - x[a]).cross(x[c] - x[a]).norm();
    const double constraint = (area - terms.rest_area[t]) / terms.rest_area[t];
    energy += 0.5 * terms.stiffness[t] * constraint * constraint;
  }
  return energy;
}

double volume_energy(std::span<const Vec3> x, const VolumeTerms& terms) {
  double energy = 0.0;
  for (std::size_t t = 0; t < terms.tets.size(); ++t) {
    const auto [i, j, k, l] = terms.tets[t];
    const double volume = (x[j] - x[i]).dot((x[k] - x[i]).cross(x[l] - x[i])) / 6.0;
    const double c = (volume - terms.rest_volume[t]) / terms.rest_volume[t];
    energy += terms.stiffness[t] * (0.5 * c * c + collapse_barrier(c + 1.0).value);
  }
  return energy;
}

}  // namespace viscera::sim
