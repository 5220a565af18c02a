#include "simulator/fluid/semi_lagrangian.h"

#include <algorithm>

#include "simulator/fluid/face_sampler.h"
#include "simulator/fluid/grid_lines.h"

namespace viscera::sim::fluid {
namespace {

/// How far the fluid at the faces of one component moves in one step, in cells per axis: its own
/// value, and each other component averaged over the four of its faces around the face (its two
/// cells, back along `axis`, and the next faces along the other axis), times Δt/h.
class FaceDisplacement {
 public:
  FaceDisplacement(const FlowGrid& grid, int axis, double time_step)
      : axis_(axis), planar_(grid.planar()), cells_per_speed_(time_step / grid.cell_size()) {
    for (int b = 0; b < 3; ++b) {
      const FaceDims d = grid.face_dims(b);
      values_[b] = grid.velocity(b).data();
      dims_[b] = d;
      stride_[b] = {1, d.x, d.x * d.y};
    }
  }

  /// Faces [begin, end) of line (j, k) into out[0..2][i]. Every face read lies in the arrays for
  /// the faces that can be active (VelocityAdvection::advect only asks for those lines).
  void line(int j, int k, int begin, int end, double* const out[3]) const {
    const double s = cells_per_speed_;
    const double* own = values_[axis_] + dims_[axis_].index(0, j, k);
    for (int i = begin; i < end; ++i)
      out[axis_][i] = s * own[i];
    for (int b = 0; b < 3; ++b) {
      if (b == axis_) continue;
      double* e = out[b];
      if (b == 2 && planar_) {
        std::fill(e + begin, e + end, 0.0);
        continue;
      }
      const double* u = values_[b] + dims_[b].index(0, j, k);
      const int back = -stride_[b][axis_], next = stride_[b][b];
      const double quarter = 0.25 * s;
      for (int i = begin; i < end; ++i)
        e[i] = quarter * (u[i] + u[i + next] + u[i + back] + u[i + back + next]);
    }
  }

 private:
  int axis_;
  bool planar_;
  double cells_per_speed_;
  const double* values_[3];
  FaceDims dims_[3];
  std::array<int, 3> stride_[3];
};

/// Calls `line(j, k, begin, end)` for the lines of component `axis` that can hold active faces
/// (a face on the grid's boundary never separates two non-solid cells), in parallel.
template <typename Line>
void for_each_inner_line(const FaceDims& d, int axis, int threads, const Line& line) {
  for_each_line(d.y, d.z, threads, [&](int j, int k) {
    if ((axis == 1 && (j == 0 || j == d.y - 1)) || (axis == 2 && (k == 0 || k == d.z - 1))) return;
    line(j, k, axis == 0 ? 1 : 0, axis == 0 ? d.x - 1 : d.x);
  });
}

}  // namespace

void VelocityAdvection::advect(FlowGrid& grid, double time_step, bool second_order, int threads) {
  const int components = grid.planar() ? 2 : 3;
  for (int axis = 0; axis < components; ++axis) {
    const FaceSampler sample(grid, axis);
    const FaceDisplacement displacement(grid, axis, time_step);
    const FaceDims d = grid.face_dims(axis);
    const auto& states = grid.face_states(axis);
    const double* old = grid.velocity(axis).data();
    auto& forward = advected_[static_cast<std::size_t>(axis)];
    forward = grid.velocity(axis);
    // The MacCormack limiter's bounds: the corners each forward value came from.
    if (second_order) low_.resize(forward.size()), high_.resize(forward.size());
    const auto trace = [&](int j, int k, int begin, int end, auto&& at_face) {
      thread_local std::vector<double> cells;
      cells.resize(3 * static_cast<std::size_t>(d.x));
      double* const e[3] = {cells.data(), cells.data() + d.x, cells.data() + 2 * d.x};
      displacement.line(j, k, begin, end, e);
      const auto row = static_cast<std::size_t>(d.index(0, j, k));
      for (int i = begin; i < end; ++i)
        if (states[row + static_cast<std::size_t>(i)] == FaceState::Active)
          at_face(row + static_cast<std::size_t>(i), i, e[0][i], e[1][i], e[2][i]);
    };
    // Each face takes the value where its fluid was one step ago.
    for_each_inner_line(d, axis, threads, [&](int j, int k, int begin, int end) {
      trace(j, k, begin, end, [&](std::size_t f, int i, double ex, double ey, double ez) {
        forward[f] = second_order
                         ? sample.at_index(old, i - ex, j - ey, k - ez, &low_[f], &high_[f])
                         : sample.at_index(old, i - ex, j - ey, k - ez);
      });
    });
    if (!second_order) continue;
    // MacCormack: trace the advected field forward again; half the round trip's error corrects
    // the first-order value, clamped to the corners it came from.
    corrected_ = forward;
    for_each_inner_line(d, axis, threads, [&](int j, int k, int begin, int end) {
      trace(j, k, begin, end, [&](std::size_t f, int i, double ex, double ey, double ez) {
        const double back = sample.at_index(forward.data(), i + ex, j + ey, k + ez);
        corrected_[f] = std::clamp(forward[f] + 0.5 * (old[f] - back), low_[f], high_[f]);
      });
    });
    std::swap(forward, corrected_);
  }
  for (int axis = 0; axis < components; ++axis)
    std::swap(grid.velocity(axis), advected_[static_cast<std::size_t>(axis)]);
}

void advect_velocity(FlowGrid& grid, double time_step, bool second_order, int threads) {
  VelocityAdvection advection;
  advection.advect(grid, time_step, second_order, threads);
}

}  // namespace viscera::sim::fluid
