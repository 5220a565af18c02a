#pragma once
/// Blood leaving a bleeding source as marker particles (seed 000 §6.2, after Foster & Metaxas
/// 1996): each particle leaves the site along the surface normal, and "the influence of the
/// emitter with its initial velocity on a particle is decaying over time, while the influence of
/// the external velocity field, induced by the flow of the distension fluid, is increasing":
///
///   v = w(a) v_emit + (1 − w(a)) v_flow(p),   w(a) = exp(−a / τ_e),   p ← p + Δt v
///
/// (explicit Euler, as the seed, in sub-steps of at most one cell). Particles do not interact
/// (seed 000 §6.2), but they do not pass into tissue either: a sub-step that would end in a
/// solid cell of the grid is not taken, and the particle's emitter push is spent on the wall. The
/// seed leaves the weights open; these sum to one, so a particle moves at its emission speed at
/// birth and with the flow once its emitter's push is spent. Each particle carries a volume of
/// blood and releases it into the concentration field (concentration_field.h) evenly over its life,
/// the rest when it dies: the field, not the particles, is what clouds the view and what the
/// outflow carries away. Blood is conserved: emitted = carried + released into the field + lost
/// outside the grid, to rounding.
///
/// Particles are stored as columns (position, emission velocity, age, blood) so the view reads
/// them without copying; their stage (age over life) picks the billboard's texture.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/math_types.h"
#include "core/random.h"
#include "simulator/fluid/artificial_vortices.h"
#include "simulator/fluid/concentration_field.h"
#include "simulator/fluid/flow_grid.h"

namespace viscera::sim::fluid {

struct BloodParticleSettings {
  double particle_volume = 0.2e-9;     ///< m³ of blood per particle (0.2 µl)
  double lifetime = 3.0;               ///< s
  double emitter_time_constant = 0.3;  ///< τ_e, s
  /// Half-angle of the cone around the normal the emission directions are drawn in, radians
  /// (a spurt is focal, not a needle).
  double spread = 0.25;
  std::size_t capacity = 10000;  ///< particles alive at once; blood past it goes to the field
};

class BloodParticles {
 public:
  BloodParticles(const BloodParticleSettings& settings, std::uint64_t seed);

  /// Emits `volume` m³ of blood at `site` (m) along the unit `normal` at `speed` m/s: whole
  /// particles of the settings' volume, the remainder kept for the next call. Blood that finds
  /// no free particle (capacity reached) goes straight into `field` at the site.
  void emit(const core::Vec3& site, const core::Vec3& normal, double speed, double volume,
            const FlowGrid& grid, ConcentrationField& field);

  /// Moves every particle through `time_step` s in the flow of `grid` (plus `vortices` when
  /// given; on all cores, bit-identical for any number), releases its blood into `field`, and
  /// retires the particles past their life.
  void advance(const FlowGrid& grid, const ArtificialVortices* vortices, ConcentrationField& field,
               double time_step);

  std::size_t size() const { return age_.size(); }
  const std::vector<core::Vec3>& positions() const { return position_; }
  const std::vector<double>& ages() const { return age_; }  ///< s
  /// Age over life of particle `i`, 0 at birth and below 1 while it lives.
  double stage(std::size_t i) const { return age_[i] / settings_.lifetime; }

  double emitted_volume() const { return emitted_; }    ///< m³ emitted so far
  double carried_volume() const;                        ///< m³ still held by particles
  double released_volume() const { return released_; }  ///< m³ given to the field
  double lost_volume() const { return lost_; }          ///< m³ released outside the grid
  /// m³ of blood handed in but not yet a whole particle.
  double pending_volume() const { return pending_; }

 private:
  /// Releases `volume` at `point` into the field (into a non-solid cell beside it when its own
  /// is solid), or books it as lost when there is none.
  void release(const FlowGrid& grid, ConcentrationField& field, const core::Vec3& point,
               double volume);
  void remove(std::size_t i);

  BloodParticleSettings settings_;
  core::Rng rng_;
  std::vector<core::Vec3> position_;
  std::vector<core::Vec3> emit_velocity_;
  std::vector<double> age_;
  std::vector<double> blood_;
  double pending_ = 0.0;
  double emitted_ = 0.0;
  double released_ = 0.0;
  double lost_ = 0.0;
};

}  // namespace viscera::sim::fluid
