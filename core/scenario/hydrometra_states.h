#pragma once
/// The hydrometra of seed 000 §2.1: an organ's pre-computed quasi-static deformation under
/// cavity pressure, "obtained for 100 different pressure settings", "loaded into the simulator
/// and piecewise linearly interpolated in real time according to the applied fluid pressures".
///
/// Computed at authoring time (simulator/dynamics/hydrometra_sweep.h), stored in the package as
/// objects/<id>/hydrometra.bin (core/package/hydrometra_file.h), interpolated each physics step
/// of a session from the distension balance's pressure (simulator/dynamics/hydrometra_forces.h).
/// Interpolation, for sorted pressures P_0 < … < P_(S−1) and per-node displacements u_k:
///   k with P_k ≤ P ≤ P_(k+1), t = (P − P_k)/(P_(k+1) − P_k), u = (1 − t) u_k + t u_(k+1),
/// clamped to u_0 below P_0 and u_(S−1) above P_(S−1) (seed-specs.md §3.1).

#include <span>
#include <string>
#include <vector>

#include "core/math_types.h"

namespace viscera::core {

/// Displacements of every body node of one organ at each of a sweep's cavity pressures.
struct HydrometraStates {
  std::vector<double> pressures;  ///< Pa, strictly increasing (the sweep starts at 0 Pa)
  int node_count = 0;             ///< body nodes per state
  /// m, state-major: state k's node n is displacements[k · node_count + n]; relative to the
  /// body's rest nodes.
  std::vector<Vec3> displacements;
  /// Convergence of the sweep (kept for the record): largest nodal force residual left, N.
  double residual = 0.0;

  bool empty() const { return pressures.empty(); }
  int state_count() const { return static_cast<int>(pressures.size()); }
  /// Displacements of state k (node_count entries).
  std::span<const Vec3> state(int k) const {
    return {displacements.data() + static_cast<std::size_t>(k) * node_count,
            static_cast<std::size_t>(node_count)};
  }

  bool operator==(const HydrometraStates&) const = default;
};

/// The two states bracketing a pressure and the weight of the upper one.
struct PressureBracket {
  int lower = 0;
  int upper = 0;
  double t = 0.0;  ///< weight of `upper`, in [0, 1]
};

/// Where `pressure` (Pa) falls among sorted `pressures` (binary search); clamped outside the
/// range (t = 0 at and below the first, the last state at and above the last). A non-finite
/// pressure clamps to the first state. Needs at least one pressure.
PressureBracket bracket_pressure(std::span<const double> pressures, double pressure);

/// The displacements at `pressure` (Pa) into `out` (node_count entries), piecewise linear in
/// pressure: exactly state k at P_k, the mean of two neighbours half way. Throws
/// core::UsageError for empty states or a wrong `out` size.
void interpolate_hydrometra(const HydrometraStates& states, double pressure, std::span<Vec3> out);

/// Checks sizes, finiteness and strictly increasing pressures; throws core::InputError naming
/// `what`.
void check_hydrometra_states(const HydrometraStates& states, const std::string& what);

}  // namespace viscera::core
