#pragma once
/// Viscera materials as the parameters of the SOFA components that carry them (SOFA v26.06).
///
/// Tet bodies (Teschner et al. 2004, seed 000 §3): distance terms on tet edges with
/// k_D = s_D · (edge's volume share), volume terms with k_V = s_V · V0, where s_D =
/// Material::distance_stiffness and s_V = Material::volume_stiffness (Pa). For a small
/// homogeneous strain ε the distance term of an edge with direction n strains it by nᵀεn;
/// averaged over isotropically oriented edges, ⟨(nᵀεn)²⟩ = (2 ε:ε + (tr ε)²)/15, so the energy
/// density ½ s_D ⟨(nᵀεn)²⟩ + ½ s_V (tr ε)² equals the linear-elastic μ ε:ε + ½ λ (tr ε)² with
///     μ = s_D / 15,   λ = s_D / 15 + s_V,
/// i.e. E = μ(3λ + 2μ)/(λ + μ) and ν = λ / (2(λ + μ)) (a pure spring net, s_V = 0, gives the
/// Cauchy value ν = 1/4): TetrahedronFEMForceField youngModulus/poissonRatio, one value per tet
/// when the wall has layers (BaseLinearElasticityFEMForceField::getYoungModulusInElement).
/// The surface area terms are left out (they act on the boundary only).
///
/// KisMo mass-spring bodies (seed 001 §3.2, simulator/physics/deformable_body.h): each tet edge
/// is a spring whose force is k1 ε with ε = (l − l0)/l0 and k1 = c₁ · share / l0 (c₁ the linear
/// coefficient of the material's stress-strain cubic, or s_D without a fit), so its constant is
///     k_e = c₁ · share / l0²   (N/m).
/// SOFA's MeshSpringForceField builds one spring per edge with stiffness S / l0
/// (MeshSpringForceField.inl, addSpring), so one `tetrahedraStiffness` S gives every edge its
/// k_e only when k_e · l0 is the same for all edges; otherwise the springs are written one by
/// one (SpringForceField, stiffness in N/m). The quadratic and cubic terms are not carried.
///
/// Damping: both models damp along the edges with c_e = s_d · share / l0² (N·s/m, s_d =
/// distance_damping), i.e. c_e = β k_e with β = s_d / c₁ (s). SOFA takes this as Rayleigh
/// stiffness damping β K of the ODE solver (EulerImplicitSolver.cpp: both the right-hand side
/// and the system matrix), which is implicit and so stable at the session step.

#include <optional>
#include <vector>

#include "core/scenario/scenario.h"

namespace viscera::exporters {

/// Parameters of SOFA's TetrahedronFEMForceField equivalent to a material.
struct SofaElasticity {
  double young_modulus = 0.0;       ///< Pa
  double poisson_ratio = 0.0;       ///< dimensionless, capped at kMaxPoissonRatio
  double rayleigh_stiffness = 0.0;  ///< β in s
};

/// SOFA's TetrahedronFEMForceField needs ν < 0.5; nearly incompressible tissue is capped here.
inline constexpr double kMaxPoissonRatio = 0.49;

/// The equivalence above. Throws core::InputError naming the material when s_D is not positive.
SofaElasticity sofa_elasticity(const core::Material& material);

/// The linear coefficient c₁ (Pa) of a KisMo material: the cubic fit's, or s_D without one.
double kismo_linear_coefficient(const core::Material& material);

/// Rayleigh stiffness coefficient β = s_d / c₁ (s) of a KisMo material; s_d / s_D for tets.
double rayleigh_stiffness(const core::Material& material, bool mass_spring);

/// The material of tet `t` of `object`: its layer's (SceneObject::layer_materials) or the
/// object's. Throws core::InputError naming the object for an unknown material id.
const core::Material& tet_material(const core::Scenario& scenario, const core::SceneObject& object,
                                   std::size_t t);

/// One linear spring as SOFA's SpringForceField stores it ("i j ks kd L").
struct SofaSpring {
  int a = 0, b = 0;
  double stiffness = 0.0;    ///< N/m
  double damping = 0.0;      ///< N·s/m
  double rest_length = 0.0;  ///< m
};

/// The springs of a KisMo body, one per tet edge in edge order (a < b), with the constants the
/// simulator builds: stiffness k_e = Σ_tets c₁ V/6 / l0² (each tet's own layer material) and
/// damping c_e = Σ_tets s_d V/6 / l0².
std::vector<SofaSpring> kismo_springs(const core::Scenario& scenario,
                                      const core::SceneObject& object);

/// The MeshSpringForceField `tetrahedraStiffness` S with S / l0 = k_e for every spring within
/// `relative_tolerance`, or nothing when no single value does.
std::optional<double> uniform_tetrahedra_stiffness(const std::vector<SofaSpring>& springs,
                                                   double relative_tolerance);

}  // namespace viscera::exporters
