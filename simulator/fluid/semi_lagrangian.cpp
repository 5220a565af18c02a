#include "simulator/fluid/semi_lagrangian.h"

#include <algorithm>
#include <array>

#include "simulator/fluid/grid_lines.h"

namespace viscera::sim::fluid {
namespace {

/// Where the fluid at `x` (moving at `start` m/s there) is `dt` s later (dt < 0: earlier), by
/// the midpoint rule in `grid`'s current velocity field.
core::Vec3 trace(const FlowGrid& grid, const core::Vec3& x, const core::Vec3& start, double dt) {
  const core::Vec3 middle = x + 0.5 * dt * start;
  return x + dt * grid.velocity_at(middle);
}

}  // namespace

void advect_velocity(FlowGrid& grid, double time_step, bool second_order, int threads) {
  const int components = grid.planar() ? 2 : 3;
  std::array<std::vector<double>, 3> advected;
  for (int axis = 0; axis < components; ++axis) {
    const FaceDims d = grid.face_dims(axis);
    const auto& states = grid.face_states(axis);
    const auto& old = grid.velocity(axis);
    auto& forward = advected[static_cast<std::size_t>(axis)];
    forward = old;
    // The MacCormack limiter's bounds: the corners each forward value came from.
    std::vector<double> low, high;
    if (second_order) low.assign(old.size(), 0.0), high.assign(old.size(), 0.0);
    for_each_line(d.y, d.z, threads, [&](int j, int k) {
      for (int i = 0; i < d.x; ++i) {
        const auto f = static_cast<std::size_t>(d.index(i, j, k));
        if (states[f] != FaceState::Active) continue;
        const core::Vec3 from = trace(grid, grid.face_position(axis, i, j, k),
                                      grid.face_velocity(axis, i, j, k), -time_step);
        forward[f] = second_order ? grid.sample(axis, old, from, &low[f], &high[f])
                                  : grid.sample(axis, old, from);
      }
    });
    if (!second_order) continue;
    // MacCormack: trace the advected field forward again; half the round trip's error corrects
    // the first-order value, clamped to the corners it came from.
    std::vector<double> corrected = forward;
    for_each_line(d.y, d.z, threads, [&](int j, int k) {
      for (int i = 0; i < d.x; ++i) {
        const auto f = static_cast<std::size_t>(d.index(i, j, k));
        if (states[f] != FaceState::Active) continue;
        const core::Vec3 x = grid.face_position(axis, i, j, k);
        const double back = grid.sample(
            axis, forward, trace(grid, x, grid.face_velocity(axis, i, j, k), time_step));
        corrected[f] = std::clamp(forward[f] + 0.5 * (old[f] - back), low[f], high[f]);
      }
    });
    forward = std::move(corrected);
  }
  for (int axis = 0; axis < components; ++axis)
    grid.velocity(axis) = std::move(advected[static_cast<std::size_t>(axis)]);
}

}  // namespace viscera::sim::fluid
