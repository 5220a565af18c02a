#pragma once
/// Where a segment or ray enters an axis-aligned box (the slab test; Ericson 2005, Real-Time
/// Collision Detection §5.3.3), for the box hierarchies of the proxy and the camera.

#include <algorithm>
#include <limits>

#include "core/math_types.h"

namespace viscera::sim {

/// The smallest t in [0, t_max] at which o + t·d lies in the box [lo, hi], or +∞ when it never
/// does. `inverse_d` is d's component-wise inverse; a zero component of d is a slab the segment
/// runs parallel to (inside it or not at all), not a division by zero.
inline double segment_enters_box(const core::Vec3& o, const core::Vec3& d,
                                 const core::Vec3& inverse_d, const core::Vec3& lo,
                                 const core::Vec3& hi, double t_max) {
  double t0 = 0.0, t1 = t_max;
  for (int a = 0; a < 3; ++a) {
    if (d[a] == 0.0) {
      if (o[a] < lo[a] || o[a] > hi[a]) return std::numeric_limits<double>::infinity();
      continue;
    }
    double near = (lo[a] - o[a]) * inverse_d[a], far = (hi[a] - o[a]) * inverse_d[a];
    if (near > far) std::swap(near, far);
    t0 = std::max(t0, near);
    t1 = std::min(t1, far);
    if (t0 > t1) return std::numeric_limits<double>::infinity();
  }
  return t0;
}

}  // namespace viscera::sim
