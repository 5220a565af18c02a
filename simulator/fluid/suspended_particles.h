#pragma once
/// Small bodies suspended in the distension fluid and carried by its flow: air bubbles, which
/// rise (seed 000 §1.1.5 and §7), and tissue debris, the shreds of a resection too small to be
/// simulated as chips, which sink (§1.1.5: "floating tissue fragments"; §7: billboards that
/// "change their behavior according to the flow of the distension fluid").
///
/// Each particle moves with the flow plus its buoyant drift along `up` at the terminal speed of
/// a small sphere, Stokes' 2Δρ g r²/(9µ), its magnitude capped at `max_drift_speed`; Δρ =
/// ρ_fluid − ρ_particle, so a bubble (Δρ ≈ 998 kg/m³) rises and tissue (ρ ≈ 1050 kg/m³ in
/// saline, Δρ ≈ −50 kg/m³) settles. Explicit sub-steps of at most half a cell.
/// - Walls: a step that would end in solid tissue is tried with the flow alone (the particle
///   slides along the wall); if that also ends in tissue it stays, resting against the wall —
///   bubbles cling under the fundus, debris lies on the posterior wall — until the flow carries
///   it away. A particle that reaches an outflow (open) cell is flushed out through the sheath;
///   one that a moving wall closes over moves to an open neighbouring cell or is lost with the
///   fluid absorbed there, as is one carried off the grid.
/// - At most `capacity` particles at once; more are not admitted.
///
/// Deterministic: particles are kept in admission order and moved one after the other.

#include <cstdint>
#include <vector>

#include "core/math_types.h"
#include "simulator/fluid/flow_grid.h"

namespace viscera::sim::fluid {

struct SuspensionSettings {
  double liquid_viscosity = 1.0e-3;   ///< µ, Pa·s (saline at 20 °C)
  double density_difference = 998.0;  ///< Δρ = ρ_fluid − ρ_particle, kg/m³ (> 0 rises)
  double gravity = 9.81;              ///< m/s²
  double max_drift_speed = 0.25;      ///< m/s
  std::size_t capacity = 200;
};

class SuspendedParticles {
 public:
  /// Throws core::UsageError for a viscosity that is not positive.
  explicit SuspendedParticles(const SuspensionSettings& settings);

  /// Buoyant drift speed of a particle of radius `radius` m along `up`, m/s (negative: sinks).
  double drift_speed(double radius) const;

  /// Admits a particle of `radius` m at `position` (m); false when at capacity.
  bool add(const core::Vec3& position, double radius);

  /// Moves every particle through `time_step` s in `grid`'s flow, drifting along the unit `up`
  /// (zero: no buoyancy), and flushes those that reach an outflow.
  void advance(const FlowGrid& grid, const core::Vec3& up, double time_step);

  std::size_t size() const { return positions_.size(); }
  const std::vector<core::Vec3>& positions() const { return positions_; }  ///< m
  const std::vector<double>& radii() const { return radii_; }              ///< m
  /// Whether particle i rests against a wall (its last drift was blocked by tissue).
  bool resting(std::size_t i) const { return resting_[i] != 0; }
  long long admitted() const { return admitted_; }
  long long flushed() const { return flushed_; }
  long long lost() const { return lost_; }  ///< closed over by tissue or carried off the grid

 private:
  void remove(std::size_t i);
  /// Moves particle i to a non-solid neighbour of its cell; false when there is none.
  bool free_from_tissue(std::size_t i, const FlowGrid& grid);

  SuspensionSettings settings_;
  std::vector<core::Vec3> positions_;
  std::vector<double> radii_;
  std::vector<std::uint8_t> resting_;
  long long admitted_ = 0, flushed_ = 0, lost_ = 0;
};

}  // namespace viscera::sim::fluid
