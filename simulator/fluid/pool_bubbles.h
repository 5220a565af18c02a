#pragma once
/// Bubbles on the laparoscopy's pool (seed 001 §4.3: "created during irrigation and simulated
/// using a particle system with Lennard-Jones forces acting between the particles and the pool
/// surface"; specs §4.8 item 8).
///
/// Decided where the seed is silent:
/// - Birth: a drop that falls into the pool faster than `entrainment_speed` (0.5 m/s) traps
///   one bubble of air where it lands, of a radius uniform in [min_radius, max_radius] from the
///   pool's seeded generator; slower drops merge without trapping air.
/// - The surface holds them: a bubble floats in the surface (the pool's level plus its waves
///   there, PoolWaves), as the stiff limit of the seed's Lennard-Jones well against the surface.
/// - Between bubbles, a Lennard-Jones force in the surface's plane with its minimum where two
///   bubbles touch (r_m = r_i + r_j): they push apart when they overlap and draw together when
///   close (floating bubbles cluster into a raft). Motion is overdamped, v = F / (6π µ r) with
///   water's µ, each step's move capped at a tenth of the bubble's radius, bubbles kept inside
///   the pool's rim.
/// - Death: each bubble bursts after a lifetime uniform in [min_life, max_life] s (drawn at
///   birth), when the pool runs dry, or when the suction cannula draws within its reach of it.
/// - At most `capacity` bubbles; air past it is not trapped.
///
/// Deterministic: bubbles are kept in birth order, forces summed in that order.

#include <vector>

#include "core/math_types.h"
#include "core/random.h"
#include "simulator/fluid/fluid_pool.h"
#include "simulator/fluid/pool_waves.h"

namespace viscera::sim::fluid {

struct PoolBubbleOptions {
  double entrainment_speed = 0.5;                   ///< m/s a drop must fall at to trap air
  double min_radius = 0.3e-3, max_radius = 1.2e-3;  ///< m
  double min_life = 1.0, max_life = 4.0;            ///< s
  double well_depth = 1e-9;  ///< J, ε of the bubbles' Lennard-Jones pair force
  double viscosity = 1e-3;   ///< Pa·s, water
  int capacity = 200;
};

struct PoolBubble {
  core::Vec3 position = core::Vec3::Zero();  ///< m, in the pool's surface
  double radius = 0.0;                       ///< m
  double age = 0.0, life = 0.0;              ///< s
};

class PoolBubbles {
 public:
  /// Throws core::InputError for radii, lives, speeds or constants that are not positive and
  /// ordered, or a capacity below 1.
  explicit PoolBubbles(PoolBubbleOptions options = {}, std::uint64_t seed = 1);

  /// A drop fell into the pool at `point` (m) moving at `velocity` (m/s): a bubble when it fell
  /// fast enough.
  void drop_lands(const core::Vec3& point, const core::Vec3& velocity, const FluidPool& pool);
  /// Moves the bubbles through `dt` s on `pool`'s surface raised by `waves`; bursts the old
  /// ones, all of them when the pool is empty, and those within `suction_reach` m of
  /// `suction_tip` when the cannula sucks (`sucking`).
  void step(double dt, const FluidPool& pool, const PoolWaves& waves, bool sucking,
            const core::Vec3& suction_tip, double suction_reach);

  const std::vector<PoolBubble>& bubbles() const { return bubbles_; }
  long long trapped() const { return trapped_; }  ///< bubbles born so far
  long long burst() const { return burst_; }      ///< bubbles gone so far
  const PoolBubbleOptions& options() const { return options_; }

 private:
  PoolBubbleOptions options_;
  core::Rng rng_;
  std::vector<PoolBubble> bubbles_;
  std::vector<core::Vec3> forces_;
  long long trapped_ = 0, burst_ = 0;
};

}  // namespace viscera::sim::fluid
