#pragma once
/// What an irrigation drop does to the tissue it hits (seed 001 §4.3, eq. 4–5; specs §4.8).
///
/// Rebound, eq. 5: the drop's velocity v_old splits into its part along the surface normal n,
/// v_N = (v_old·n) n, and the rest, v_T = v_old − v_N; it leaves with
///   v_new = (1 − µ) v_T − ε v_N,
/// ε the elasticity (0: the drop sticks to the surface, 1: a perfect bounce) and µ the friction
/// (0: it slides on freely, 1: it loses its whole slide).
///
/// Impact force, eq. 4 as read in the specs: the knot that is hit is pushed along the drop's
/// incoming direction in proportion to the kinetic energy the drop lost,
///   F = m · k · (v_old / |v_old|) · (|v_old|² − |v_new|²).
/// The paper calls k a spring constant and gives no units; here k is 1/(2 d) in 1/m, d the
/// depth over which the drop is stopped, so that F · d = ½ m (|v_old|² − |v_new|²) (the work–
/// energy theorem) and F comes out in N.

#include "core/math_types.h"

namespace viscera::sim::fluid {

/// The drop's velocity after it hits a surface of unit normal `normal` (either orientation)
/// with velocity `v_old` (m/s), eq. 5; `elasticity` ε and `friction` µ in [0, 1].
core::Vec3 rebound_velocity(const core::Vec3& v_old, const core::Vec3& normal, double elasticity,
                            double friction);

/// The force in N on the hit knot, eq. 4: `mass` kg, `k` 1/m, velocities before and after in
/// m/s. Zero for a drop at rest, and never pulls (a drop that left faster pushes nothing).
core::Vec3 impact_force(double mass, double k, const core::Vec3& v_old, const core::Vec3& v_new);

}  // namespace viscera::sim::fluid
