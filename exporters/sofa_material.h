#pragma once
/// Viscera materials as SOFA force-field parameters. Our bodies use Teschner et al. 2004
/// energies (seed 000 §3): distance terms on tet edges with k_D = s_D · (edge's volume share),
/// volume terms with k_V = s_V · V0, where s_D = Material::distance_stiffness and
/// s_V = Material::volume_stiffness (Pa). For a small homogeneous strain ε the distance term of
/// an edge with direction n strains it by nᵀεn; averaged over isotropically oriented edges,
/// ⟨(nᵀεn)²⟩ = (2 ε:ε + (tr ε)²)/15, so the energy density ½ s_D ⟨(nᵀεn)²⟩ + ½ s_V (tr ε)² equals
/// the linear-elastic μ ε:ε + ½ λ (tr ε)² with
///     μ = s_D / 15,   λ = s_D / 15 + s_V,
/// i.e. E = μ(3λ + 2μ)/(λ + μ) and ν = λ / (2(λ + μ)) (a pure spring net, s_V = 0, gives the
/// Cauchy value ν = 1/4). The surface area terms are left out (they act on the boundary only).
/// Damping: the distance terms are damped with k_d = s_d · share (s_d = distance_damping, Pa·s),
/// i.e. s_d/s_D times their stiffness, which SOFA expresses as Rayleigh stiffness damping
/// β = s_d / s_D (s). KisMo mass-spring bodies (seed 001 §3.2) have per-edge springs
/// k = c₁ · share / L0² (N/m) with c₁ the cubic fit's linear coefficient, or s_D without a fit;
/// SOFA's MeshSpringForceField takes one stiffness per mesh, the mean over the edges.

#include "core/mesh/tet_mesh.h"
#include "core/scenario/material.h"

namespace viscera::exporters {

/// Parameters of SOFA's TetrahedronFEMForceField equivalent to a material.
struct SofaElasticity {
  double young_modulus = 0.0;       ///< Pa
  double poisson_ratio = 0.0;       ///< dimensionless, capped at kMaxPoissonRatio
  double rayleigh_stiffness = 0.0;  ///< s
};

/// SOFA's TetrahedronFEMForceField needs ν < 0.5; nearly incompressible tissue is capped here.
inline constexpr double kMaxPoissonRatio = 0.49;

/// The equivalence above. Throws core::InputError naming the material when s_D is not positive.
SofaElasticity sofa_elasticity(const core::Material& material);

/// Parameters of SOFA's MeshSpringForceField for a KisMo body.
struct SofaSprings {
  double stiffness = 0.0;  ///< N/m, mean over the body's edges
  double damping = 0.0;    ///< N·s/m, mean over the body's edges
};

/// The mean spring constants of `body`'s edges under `material`, as the simulator builds them.
SofaSprings sofa_springs(const core::Material& material, const core::TetMesh& body);

}  // namespace viscera::exporters
