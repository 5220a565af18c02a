#pragma once
/// The suction–irrigation cannula in a laparoscopy session (seed 001 §4.3; issue 19 §3): the
/// "suction" tool of the working port has two trumpet valves, as real ones. With its
/// irrigation valve open (InstrumentState::irrigating) the jet leaves the tip along the shaft
/// (fluid::IrrigationJet: 10 ml/s at 0.8 m/s, 0.01 ml drops); drops hit the surfaces of the
/// world's bodies, push the hit knots (eq. 4, as ImpactForces that the next physics step
/// applies) and rebound (eq. 5); drops that come to rest gather in the pool
/// (fluid::FluidPool) together with the blood the session's bleeding sources let out. With its
/// suction valve open (InstrumentState::jaws_closed) and the tip within 5 mm of the pool's
/// surface or under it, the cannula draws the pool off at 15 ml/s, water and blood in
/// proportion (it draws off smoke too: LaparoscopicTools).
///
/// The pool lies across gravity over the lowest surface knot of the world's bodies at rest
/// (−z when the world has no gravity), spread over the pelvic floor's 50 cm²
/// (FluidPool::kPelvicPoolArea). The drops collide with each body's surface triangles through a
/// bounding-volume hierarchy (SurfaceBvh, the paper's "hierarchical collision tests with
/// bounding boxes"), refitted to the bodies' positions in every step that has drops in flight
/// and built anew when a body's surface changes (a cut). The jet and the pool are not part of
/// the state hash; the forces the drops put on the tissue are, through the knots they move.
/// Drops that fall into the pool's surface raise waves on it (fluid::PoolWaves), which run and
/// die out in every step while the pool holds water, and the fast ones trap bubbles that float
/// on it (fluid::PoolBubbles) until they burst or the suction takes them.

#include <memory>
#include <optional>
#include <vector>

#include "simulator/camera/surface_bvh.h"
#include "simulator/dynamics/impact_forces.h"
#include "simulator/fluid/fluid_pool.h"
#include "simulator/fluid/irrigation_jet.h"
#include "simulator/fluid/pool_bubbles.h"
#include "simulator/fluid/pool_waves.h"
#include "simulator/session/instrument_state.h"
#include "simulator/session/laparoscopy_summary.h"
#include "simulator/world/world.h"

namespace viscera::sim {

struct SuctionIrrigationOptions {
  fluid::JetOptions jet;
  fluid::SuctionOptions suction;
  double pool_area = fluid::FluidPool::kPelvicPoolArea;  ///< m²
};

class SuctionIrrigation {
 public:
  /// The jet, no drops, and an empty pool under the bodies of `world` (those with tets and a
  /// surface). Throws core::InputError for unusable options.
  explicit SuctionIrrigation(const World& world, SuctionIrrigationOptions options = {});

  /// After every physics step of `dt` s with the instrument in `state`: blood the session's
  /// sources let out since the last call (`blood_released` m³ in all, never decreasing) joins
  /// the pool; the jet emits while the cannula irrigates and its drops fly, hit, and land; the
  /// drops' impacts become the world's impact forces for the next step (waking a sleeping
  /// world); the suction draws off the pool. Records the volumes in `summary`.
  void follow(const InstrumentState& state, World& world, double dt, double blood_released,
              LaparoscopySummary& summary);

  const fluid::IrrigationJet& jet() const { return jet_; }
  const fluid::FluidPool& pool() const { return pool_; }
  const fluid::PoolWaves& waves() const { return waves_; }
  const fluid::PoolBubbles& bubbles() const { return bubbles_; }
  /// The impacts of the last call, N and m.
  const std::vector<fluid::JetImpact>& last_impacts() const { return impacts_; }
  /// The drops of the last call that fell into the pool's surface.
  const std::vector<fluid::PoolLanding>& last_landings() const { return landings_; }

 private:
  /// The first surface of the bodies the segment meets (bodies in order, nearest hit).
  std::optional<fluid::SurfaceHit> first_hit(const core::Vec3& from, const core::Vec3& to) const;
  /// Refits each body's hierarchy to its positions, rebuilding it when its surface changed.
  void refresh_surfaces(const World& world);
  void apply_impacts(World& world);

  SuctionIrrigationOptions options_;
  std::vector<int> bodies_;  ///< world bodies the drops collide with
  fluid::IrrigationJet jet_;
  fluid::FluidPool pool_;
  fluid::PoolWaves waves_;
  fluid::PoolBubbles bubbles_;
  std::vector<SurfaceBvh> surfaces_;
  std::vector<std::vector<core::Triangle>> triangles_;  ///< per body, what its hierarchy holds
  std::vector<fluid::JetImpact> impacts_;
  std::vector<fluid::PoolLanding> landings_;
  ImpactForces* forces_ = nullptr;  ///< added to the world at the first impact
  double blood_seen_ = 0.0;         ///< m³ of the sources' blood already in the pool
};

/// The pool a session's world starts with: its floor the lowest surface knot at rest along
/// gravity (−z without gravity) among `bodies`, over `area` m².
fluid::FluidPool pool_under(const World& world, const std::vector<int>& bodies, double area);

}  // namespace viscera::sim
