#pragma once
/// Organ motility as displacements of an object's knots (seed 001 §5.2, eq. 6–7): periodic
/// motion from travelling sine waves plus impulsive contractions, for the studio's animated
/// preview and for a runtime that moves knots by it. Plain functions of the rest positions and
/// time; the same (spec, rest positions, seed) give the same displacements.
///
/// Per knot i (initialised once, as the seed's directions u_i):
///   u_r,i  unit radial direction from the object's principal axis a through its centroid,
///   x_i    position along the wave direction wD (m), measured from the centroid,
///   A_i    = Δp_mean + sgn(ρ − ½) · ρ' · √Δp_var      (eq. 7; ρ, ρ' uniform in [0, 1)),
///   f_i    = fr + frD · ρ''                              (eq. 6: the frequency disturbance),
/// and the displacement at time t (s) is
///   d_i(t) = A_i [ sin φ_i(t) u_r,i + ½ cos φ_i(t) a ] − c(t) Δp_mean u_r,i,
///   φ_i(t) = 2π f_i (t − x_i / wS),
/// the radial term the seed's F0 (inflating and deflating rings), the longitudinal term its F1
/// (rings moving along the axis, a quarter period behind). c(t) ∈ [0, 1] is the impulsive
/// contraction: one per interval of contraction_interval_mean (its time jittered uniformly by
/// ±√variance, at most ±0.4 of the interval), each rising and falling as (s/τ) e^{1 − s/τ} with
/// τ = 0.15 s after its start s = 0. Lengths in m, times in s.

#include <cstdint>
#include <vector>

#include "core/math_types.h"
#include "core/scenario/scenario_parts.h"

namespace viscera::sim {

class OrganMotility {
 public:
  /// Throws core::UsageError for an empty knot set, a non-positive wave speed or a zero wave
  /// direction.
  OrganMotility(const core::MotilitySpec& spec, std::vector<core::Vec3> rest, std::uint64_t seed);

  std::size_t size() const { return rest_.size(); }
  /// The displacement of knot `i` at time `t`.
  core::Vec3 displacement(std::size_t i, double t) const;
  /// Every knot's position at time `t`: rest + displacement.
  std::vector<core::Vec3> positions(double t) const;
  /// The impulsive contraction c(t) ∈ [0, 1].
  double contraction(double t) const;
  /// The principal axis a (unit) and the centroid it passes through.
  const core::Vec3& axis() const { return axis_; }
  const core::Vec3& centroid() const { return centroid_; }

 private:
  core::Vec3 displacement_with(std::size_t i, double t, double contraction) const;

  core::MotilitySpec spec_;
  std::uint64_t seed_;
  std::vector<core::Vec3> rest_, radial_;
  std::vector<double> along_, amplitude_, frequency_;
  core::Vec3 axis_ = core::Vec3::UnitZ(), centroid_ = core::Vec3::Zero();
};

}  // namespace viscera::sim
