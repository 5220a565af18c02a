#pragma once
/// Artificial vortices superimposed on the solver's flow (seed 000 §2.2: the cavity's Reynolds
/// number is about 30,000, far above what a coarse grid resolves, so "for higher flow rates,
/// artificial vortices are added"; "the resulting flow velocity can be computed by superimposing
/// the flow provided by the fluid solver and the velocity originating from the various
/// vortices"). The seed states neither kernel, strength nor lifetime; decided here:
/// - kernel: the Lamb–Oseen vortex, v = Γ/(2πr)·(1 − exp(−r²/r_c²)) around its axis —
///   divergence-free, finite at the axis, the classic viscous vortex;
/// - a vortex is born in a random fluid cell with a random axis when the inflow exceeds
///   `threshold_flow`; the number kept grows with the excess up to `max_count`;
/// - its circulation is `circulation_per_flow` × inflow, its core `core_radius`; it drifts with
///   the solver's flow and fades linearly to nothing over `lifetime`.
/// Deterministic for a seed: the same inflow history gives the same vortices.

#include <cstdint>
#include <vector>

#include "core/random.h"
#include "simulator/fluid/flow_grid.h"

namespace viscera::sim::fluid {

struct VortexSettings {
  double threshold_flow = 2.0e-6;       ///< m³/s (120 ml/min): no vortices below
  double flow_per_vortex = 1.0e-6;      ///< m³/s of inflow above the threshold per vortex kept
  int max_count = 20;                   ///< seed 000 Fig. 3 shows 20
  double circulation_per_flow = 200.0;  ///< Γ per inflow, (m²/s)/(m³/s) = 1/m: 300 ml/min
                                        ///< gives a 5 cm/s peak at r_c = 2 mm
  double core_radius = 0.002;           ///< r_c, m
  double lifetime = 2.0;                ///< s
};

struct Vortex {
  core::Vec3 centre = core::Vec3::Zero();  ///< m
  core::Vec3 axis = core::Vec3::UnitZ();   ///< unit
  double circulation = 0.0;                ///< Γ at birth, m²/s
  double age = 0.0;                        ///< s
};

/// The Lamb–Oseen velocity at `point` of one vortex of circulation `circulation` (m/s).
core::Vec3 lamb_oseen_velocity(const Vortex& vortex, double circulation, double core_radius,
                               const core::Vec3& point);

class ArtificialVortices {
 public:
  ArtificialVortices(const VortexSettings& settings, std::uint64_t seed);

  /// Ages, moves and replaces the vortices for `time_step` s at an inflow of `inflow` m³/s in
  /// `grid` (vortices live in its fluid cells).
  void advance(const FlowGrid& grid, double inflow, double time_step);

  /// The vortices' velocity at `point`, m/s, to add to the solver's.
  core::Vec3 velocity(const core::Vec3& point) const;
  /// The solver's velocity plus the vortices'.
  core::Vec3 flow_velocity(const FlowGrid& grid, const core::Vec3& point) const {
    return grid.velocity_at(point) + velocity(point);
  }

  const std::vector<Vortex>& vortices() const { return vortices_; }

 private:
  double strength(const Vortex& vortex) const;

  VortexSettings settings_;
  core::Rng rng_;
  std::vector<Vortex> vortices_;
};

}  // namespace viscera::sim::fluid
