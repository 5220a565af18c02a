#pragma once
/// From a tissue's stress-strain cubic to the constants the simulator consumes (seed 001 §3.2
/// "used to set up the spring constants correctly"; DESIGN.md §3 Material).
///
/// KisMo springs (BodyKind::MassSpring) read the cubic itself: the simulator gives each spring
/// k_n = c_n · A with A = (the spring's volume share) / l0 (kismo_mass_spring.h,
/// deformable_body.cpp), so StressStrainCurve::cubic = {0, c1, c2, c3} is passed on unchanged.
///
/// Teschner energies (BodyKind::TetMesh) are quadratic, so the cubic is first replaced by the
/// line through the origin closest to it in least squares over the working strain range
/// [0, ε_w]:  E = c1 + ¾ c2 ε_w + ⅗ c3 ε_w².  The constants then follow from linear
/// elasticity of the edge network. An edge of volume share V_e and stiffness density s stores
/// ½ s V_e (nᵀεn)² under a uniform small strain ε; averaged over isotropically oriented edges,
/// ⟨(nᵀεn)²⟩ = (2 ε:ε + (tr ε)²) / 15, so the network has Lamé parameters μ = λ = s / 15 (the
/// Cauchy relation of central-force networks, ν = ¼, Young's modulus s / 6 — the "effective
/// modulus about a fifth of distance_stiffness" the ball template states). The volume term
/// ½ k_V ((V − V0)/V0)² with k_V = v V0 adds v to λ. Matching a tissue of modulus E and
/// Poisson's ratio ν (μ_t = E / 2(1+ν), λ_t = E ν / (1+ν)(1−2ν)) therefore gives
///   distance_stiffness s = 15 μ_t,   volume_stiffness v = λ_t − μ_t   (needs ν ≥ ¼),
/// and a surface membrane of thickness t (a capsule or serosa) resists area change with the
/// 2-D bulk modulus  area_stiffness = E t / 2(1 − ν)  (N/m).

#include <array>
#include <string>

#include "core/scenario/material.h"

namespace viscera::core {

/// How the linear constants are taken from the cubic.
struct ElasticityOptions {
  double poisson_ratio = 0.45;  ///< ν in [0.25, 0.5); soft tissue is nearly incompressible
  double working_strain = 0.0;  ///< ε_w of the linearisation; 0 = the largest measured |strain|
  double membrane_thickness = 0.0;  ///< m of a surface membrane; 0 = no area stiffness
};

/// The derived constants, with the intermediate moduli for reports.
struct TeschnerConstants {
  double working_strain = 0.0;      ///< ε_w used
  double linear_modulus = 0.0;      ///< E in Pa
  double shear_modulus = 0.0;       ///< μ in Pa
  double lame_lambda = 0.0;         ///< λ in Pa
  double distance_stiffness = 0.0;  ///< Pa
  double volume_stiffness = 0.0;    ///< Pa
  double area_stiffness = 0.0;      ///< N/m
};

/// E of the least-squares line through the origin to the cubic on [0, working_strain] in Pa.
/// Throws UsageError for a working strain that is not positive.
double linearised_modulus(const std::array<double, 4>& cubic, double working_strain);

/// The Teschner constants of a cubic. Throws UsageError for ν outside [0.25, 0.5) or a
/// negative membrane thickness, and ValidationError when the cubic's tangent modulus is not
/// positive everywhere on [0, ε_w] (such a tissue would snap through: the fit is unusable).
TeschnerConstants teschner_constants(const std::array<double, 4>& cubic, double working_strain,
                                     const ElasticityOptions& options);

/// The strain at which the cubic reaches `stress` Pa on [0, limit] (bisection on the monotone
/// curve), or `limit` when it does not get there.
double strain_at_stress(const std::array<double, 4>& cubic, double stress, double limit);

/// A material from a measured curve: fits the cubic (cubic_stress_fit.h), checks and derives
/// the constants, and keeps everything else from `base` (density, damping, tearing, plastic
/// yield, name). Throws as fit_cubic_stress and teschner_constants.
Material material_from_measured_curve(const StressStrainCurve& measured,
                                      const ElasticityOptions& options, Material base);

}  // namespace viscera::core
