#pragma once
/// Teschner et al. 2004 deformation energies (seed 000 §3, eq. 3–7), as plain functions over
/// arrays. Each constraint C is zero at rest and normalised by its rest measure, its energy is
/// E = ½ k C², and the force on point i is F_i = (−k C − k_d Σ_j ∂C/∂p_j · v_j) ∂C/∂p_i (eq. 7).
/// Damping acts on distance terms only, as the paper recommends. The functions ADD forces to
/// `forces` and return the potential energy of their terms in J.

#include <span>
#include <vector>

#include "core/math_types.h"

namespace viscera::sim {

using core::Vec3;

/// Distance terms on tetrahedral edges (eq. 4): C = (|p_j − p_i| − D0) / D0.
struct DistanceTerms {
  std::vector<std::array<int, 2>> edges;
  std::vector<double> rest_length;  ///< D0 in m
  std::vector<double> stiffness;    ///< k_D in J
  std::vector<double> damping;      ///< k_d in J·s
};

/// Area terms on surface triangles (eq. 5): C = (A − A0) / A0.
struct AreaTerms {
  std::vector<core::Triangle> triangles;
  std::vector<double> rest_area;  ///< A0 in m²
  std::vector<double> stiffness;  ///< k_A in J
};

/// Volume terms on tetrahedra (eq. 6) with the SIGNED volume, so an inverted tet is pushed
/// back to its rest orientation: C = (V − V0) / V0, J = V / V0 = C + 1.
///
/// Collapse barrier. Eq. 6 alone, E = ½ k_V C², resists a collapsing tet with a force that stays
/// finite at V = 0 (k_V times a third of a face area per node): any load above it — an
/// instrument pressing on a few surface nodes of a soft wall — crushes the tet through zero
/// volume and turns it inside out, although tissue (nearly incompressible) can never be
/// squeezed to nothing. So each volume term also carries the barrier of Li et al. 2020
/// (Incremental Potential Contact, eq. 6) on J, active below Ĵ = kCollapseBarrierStart:
///   E_b = k_V b(J),  b(J) = −(J − Ĵ)² ln(J / Ĵ) for 0 < J < Ĵ, 0 for J ≥ Ĵ,
/// C² continuous at Ĵ, convex, and infinite as J → 0⁺: no finite load collapses a tet, and the
/// implicit integrator (whose line search only accepts finite, decreasing energies) never
/// turns one inside out. A tet already inverted (J ≤ 0, e.g. a tangled input) has infinite
/// energy and gets the barrier force of J = Ĵ/1000 on top of eq. 6's, pushing it back.
struct VolumeTerms {
  std::vector<core::Tetrahedron> tets;
  std::vector<double> rest_volume;  ///< V0 in m³
  std::vector<double> stiffness;    ///< k_V in J
};

/// Start Ĵ of the collapse barrier (a fifth of the rest volume).
inline constexpr double kCollapseBarrierStart = 0.2;

/// b(J), b′(J), b″(J) of the collapse barrier above (b = +∞ for J ≤ 0; b′, b″ then those of
/// J = Ĵ/1000).
struct CollapseBarrier {
  double value = 0.0, first = 0.0, second = 0.0;
};
CollapseBarrier collapse_barrier(double j);

/// Adds distance forces (with damping from `velocities`, m/s) and returns their energy.
double add_distance_forces(std::span<const Vec3> positions, std::span<const Vec3> velocities,
                           const DistanceTerms& terms, std::span<Vec3> forces);

/// Adds area-preservation forces and returns their energy.
double add_area_forces(std::span<const Vec3> positions, const AreaTerms& terms,
                       std::span<Vec3> forces);

/// Adds volume-preservation forces and returns their energy.
double add_volume_forces(std::span<const Vec3> positions, const VolumeTerms& terms,
                         std::span<Vec3> forces);

/// Potential energies alone (no forces), for checks and reports.
double distance_energy(std::span<const Vec3> positions, const DistanceTerms& terms);
double area_energy(std::span<const Vec3> positions, const AreaTerms& terms);
double volume_energy(std::span<const Vec3> positions, const VolumeTerms& terms);

}  // namespace viscera::sim
