#pragma once
/// Air bubbles in the distension fluid (seed 000 §1.1.5: "obscurations during interventions can
/// be caused by endometrial bleeding, floating tissue fragments, or air bubbles … the gynecologist
/// has to learn to correctly dose the in- and outflow"; §7: they are billboards that "change their
/// behavior according to the flow of the distension fluid").
///
/// Decided where the seed is silent:
/// - Source: air carried in with the distension fluid. Each time the pump's inflow starts after
///   a pause of at least `pause_before_burst` s (a valve opened, a new bag), the tubing's air
///   arrives as a burst of `burst_count` bubbles; while it runs, one more bubble every
///   `inflow_per_bubble` m³ delivered. Radii are uniform in [min_radius, max_radius] from the
///   session's seeded generator. Bubbles are born at the inflow, spread over a cell.
/// - Motion (suspended_particles.h): each bubble moves with the flow plus its buoyant rise
///   along `up` at the terminal speed of a small sphere in water, Stokes' 2Δρ g r²/(9µ), capped
///   at `max_rise_speed` (millimetre bubbles rise at 0.2–0.3 m/s; Clift, Grace & Weber 1978);
///   it clings under walls (the fundus, the anterior wall) until the flow carries it away, and
///   an outflow flushes it.
/// - At most `capacity` bubbles at once; air past it is not admitted.
///
/// Deterministic: bubbles are kept in birth order and moved one after the other.

#include <cstdint>
#include <vector>

#include "core/math_types.h"
#include "core/random.h"
#include "simulator/fluid/flow_grid.h"
#include "simulator/fluid/suspended_particles.h"

namespace viscera::sim::fluid {

struct AirBubbleSettings {
  int burst_count = 12;               ///< bubbles when the inflow starts after a pause
  double pause_before_burst = 1.0;    ///< s without inflow before a start brings a burst
  double inflow_per_bubble = 5e-6;    ///< m³ of inflow per bubble while it runs (one per 5 ml)
  double min_radius = 0.2e-3;         ///< m
  double max_radius = 0.8e-3;         ///< m
  double max_rise_speed = 0.25;       ///< m/s
  double liquid_viscosity = 1.0e-3;   ///< µ, Pa·s (saline at 20 °C)
  double density_difference = 998.0;  ///< Δρ between saline and air, kg/m³
  double gravity = 9.81;              ///< m/s²
  std::size_t capacity = 200;
};

class AirBubbles {
 public:
  AirBubbles(const AirBubbleSettings& settings, std::uint64_t seed);

  /// Terminal rise speed of a bubble of radius `radius` m, m/s.
  double rise_speed(double radius) const;

  /// Books `inflow_rate` m³/s of pump inflow over `time_step` s entering at `inlet` (m):
  /// the burst when it starts after a pause, then one bubble per inflow_per_bubble.
  void admit(double inflow_rate, double time_step, const core::Vec3& inlet, const FlowGrid& grid);

  /// Moves every bubble through `time_step` s in `grid`'s flow, rising along the unit `up`
  /// (zero: no buoyancy), and flushes those that reach an outflow.
  void advance(const FlowGrid& grid, const core::Vec3& up, double time_step);

  std::size_t size() const { return bubbles_.size(); }
  const std::vector<core::Vec3>& positions() const { return bubbles_.positions(); }  ///< m
  const std::vector<double>& radii() const { return bubbles_.radii(); }              ///< m
  /// Whether bubble i clings under a wall (its last rise was blocked by tissue).
  bool clinging(std::size_t i) const { return bubbles_.resting(i); }
  long long admitted() const { return bubbles_.admitted(); }
  long long flushed() const { return bubbles_.flushed(); }
  long long lost() const { return bubbles_.lost(); }  ///< closed over by tissue or off the grid

 private:
  void add(const core::Vec3& at, const FlowGrid& grid);

  AirBubbleSettings settings_;
  core::Rng rng_;
  SuspendedParticles bubbles_;
  double idle_ = 1e9;  ///< s since the inflow last ran
  double inflow_since_bubble_ = 0.0;
};

}  // namespace viscera::sim::fluid
