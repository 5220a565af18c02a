#include "simulator/fluid/semi_lagrangian.h"

#include <algorithm>
#include <array>

#include "simulator/fluid/face_sampler.h"
#include "simulator/fluid/grid_lines.h"

namespace viscera::sim::fluid {
namespace {

/// The whole velocity at the faces of one component, m/s: the face's own value, and each other
/// component averaged over the four of its faces around this one (its two cells, back along
/// `axis`, and the next faces along the other axis) — FlowGrid::face_velocity with the strides
/// taken once.
class FaceVelocity {
 public:
  FaceVelocity(const FlowGrid& grid, int axis) : axis_(axis), planar_(grid.planar()) {
    for (int b = 0; b < 3; ++b) {
      const FaceDims d = grid.face_dims(b);
      values_[b] = grid.velocity(b).data();
      dims_[b] = d;
      stride_[b] = {1, d.x, d.x * d.y};
    }
  }

  core::Vec3 operator()(int i, int j, int k, double own) const {
    core::Vec3 v;
    v[axis_] = own;
    for (int b = 0; b < 3; ++b) {
      if (b == axis_) continue;
      if (b == 2 && planar_) {
        v[b] = 0.0;
        continue;
      }
      const auto& s = stride_[b];
      const double* u = values_[b] + dims_[b].index(i, j, k);
      const int back = -s[axis_], next = s[b];
      v[b] = 0.25 * (u[0] + u[next] + u[back] + u[back + next]);
    }
    return v;
  }

 private:
  int axis_;
  bool planar_;
  const double* values_[3];
  FaceDims dims_[3];
  std::array<int, 3> stride_[3];
};

}  // namespace

void advect_velocity(FlowGrid& grid, double time_step, bool second_order, int threads) {
  const int components = grid.planar() ? 2 : 3;
  std::array<std::vector<double>, 3> advected;
  const double h = grid.cell_size();
  for (int axis = 0; axis < components; ++axis) {
    const FaceSampler sample(grid, axis);
    const FaceVelocity velocity(grid, axis);
    const FaceDims d = grid.face_dims(axis);
    const auto& states = grid.face_states(axis);
    const auto& old = grid.velocity(axis);
    auto& forward = advected[static_cast<std::size_t>(axis)];
    forward = old;
    // The MacCormack limiter's bounds: the corners each forward value came from.
    std::vector<double> low, high;
    if (second_order) low.assign(old.size(), 0.0), high.assign(old.size(), 0.0);
    core::Vec3 corner = grid.origin() + 0.5 * h * core::Vec3::Ones();
    corner[axis] -= 0.5 * h;
    // The face's own velocity, traced straight back: the position it came from.
    const auto place = [&](int i, int j, int k) {
      return core::Vec3(corner + h * core::Vec3(i, j, k));
    };
    for_each_line(d.y, d.z, threads, [&](int j, int k) {
      for (int i = 0; i < d.x; ++i) {
        const auto f = static_cast<std::size_t>(d.index(i, j, k));
        if (states[f] != FaceState::Active) continue;
        const core::Vec3 from = place(i, j, k) - time_step * velocity(i, j, k, old[f]);
        forward[f] =
            second_order ? sample(old.data(), from, &low[f], &high[f]) : sample(old.data(), from);
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
        const core::Vec3 to = place(i, j, k) + time_step * velocity(i, j, k, old[f]);
        const double back = sample(forward.data(), to);
        corrected[f] = std::clamp(forward[f] + 0.5 * (old[f] - back), low[f], high[f]);
      }
    });
    forward = std::move(corrected);
  }
  for (int axis = 0; axis < components; ++axis)
    grid.velocity(axis) = std::move(advected[static_cast<std::size_t>(axis)]);
}

}  // namespace viscera::sim::fluid
