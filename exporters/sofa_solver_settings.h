#pragma once
/// The settings of the scene's one EulerImplicitSolver + CGLinearSolver and of its collision
/// pipeline, derived from the scene's masses, stiffness and step (SOFA v26.06). Internal to
/// exporters/.
///
/// Implicit Euler (EulerImplicitSolver.cpp, solve()): A Δv = b with
///     A = M (1 + h r_m) − h (h + r_s) K,   b = h (f + (h + r_s) K v − r_m M v),
/// K = ∂f/∂x (negative semi-definite at rest), so A ⪰ M. CG (CGLinearSolver.inl, solve()) stops
/// when |r| / |b| ≤ tolerance, or when the denominator pᵀAp falls to `threshold` or below.
/// CG must stop on the tolerance, so the threshold has to stay far below every pᵀAp it meets:
/// pᵀAp ≥ m_min |p|², and the last directions p are as small as the residual it must still
/// reduce, tolerance · |b|, where |b| ≥ h m_min g (one free node's weight over a step; g the
/// session gravity, or 9.81 m/s² when it is off, as the scale of the loads the tools apply):
///     smallest pᵀAp ≈ m_min (tolerance h m_min g)²,   threshold = 10⁻⁶ × that.
/// Iterations: CG reaches the tolerance in at most ½ √κ ln(2 / tolerance) steps, κ ≤
/// max_i (m_i + h (h + r_s) k_i) / m_min with k_i the Gershgorin row sum of −K at node i.
///
/// Contact (BarycentricPenalityContact.inl, setDetectionOutputs; PenalityContactForceField.inl,
/// addForce): each contact pushes with k (d0 − distance) along the normal, k = k₁ k₂ / d0, where
/// k₁, k₂ are the two collision models' contactStiffness and d0 the intersection's
/// contactDistance (proximities 0). Each model gets √(k_V d0) so that k equals Viscera's penalty
/// stiffness per colliding point k_V (SessionSpec::contact_stiffness, N/m).

#include <vector>

#include "core/scenario/scenario.h"
#include "exporters/sofa_body.h"

namespace viscera::exporters {

struct SofaSolverSettings {
  double rayleigh_stiffness = 0.0;  ///< r_s in s: the bodies' common β, or their mass-weighted mean
  bool rayleigh_exact = true;       ///< every free body's material has this β
  double tolerance = 1e-6;          ///< |r| / |b| at which CG stops
  double smallest_denominator = 0.0;  ///< estimated smallest pᵀAp, kg·m²/s²
  double threshold = 0.0;             ///< CG's denominator threshold, kg·m²/s²
  int iterations = 0;                 ///< CG's iteration limit
};

/// Penalty contact as SOFA's collision pipeline carries it; `enabled` when the session has
/// contact (stiffness > 0 and two or more bodies, as simulator/world does).
struct SofaContact {
  bool enabled = false;
  double stiffness = 0.0;         ///< k_V, N/m per contact
  double contact_distance = 0.0;  ///< d0 in m (MinProximityIntersection contactDistance)
  double alarm_distance = 0.0;    ///< m, where pairs start being tested
  double model_stiffness = 0.0;   ///< contactStiffness of each collision model, √(k_V d0)
};

SofaContact sofa_contact(const core::Scenario& scenario, const std::vector<SofaBody>& bodies);

SofaSolverSettings sofa_solver_settings(const core::Scenario& scenario,
                                        const std::vector<SofaBody>& bodies,
                                        const SofaContact& contact);

/// The boundary triangles of a body (its stored surface faces, or derived from its tets).
std::vector<core::Triangle> body_surface(const core::TetMesh& body);

}  // namespace viscera::exporters
