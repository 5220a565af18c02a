#include "simulator/fluid/flow_grid.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "core/error.h"
#include "simulator/fluid/face_sampler.h"

namespace viscera::sim::fluid {
namespace {

constexpr std::array<std::array<int, 3>, 3> kAxis{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

std::atomic<std::uint64_t> next_labelling{1};

}  // namespace

FlowGrid::FlowGrid(int nx, int ny, int nz, double cell_size, const core::Vec3& origin)
    : nx_(nx), ny_(ny), nz_(nz), h_(cell_size), origin_(origin) {
  if (nx < 1 || ny < 1 || nz < 1)
    throw core::UsageError("a flow grid needs at least one cell along each axis");
  if (!(cell_size > 0.0) || !std::isfinite(cell_size))
    throw core::UsageError("a flow grid's cell size must be a positive length in m");
  cells_.assign(static_cast<std::size_t>(cell_count()), FlowCell::Fluid);
  solid_velocity_.assign(cells_.size(), core::Vec3::Zero());
  pressure_.assign(cells_.size(), 0.0);
  for (int axis = 0; axis < 3; ++axis) {
    velocity_[axis].assign(static_cast<std::size_t>(face_dims(axis).count()), 0.0);
    states_[axis].assign(velocity_[axis].size(), FaceState::Active);
  }
  update_faces();
}

void FlowGrid::set_cell(int i, int j, int k, FlowCell cell, const core::Vec3& velocity) {
  const auto c = static_cast<std::size_t>(cell_index(i, j, k));
  if (cells_[c] != cell) relabelled_ = true;
  cells_[c] = cell;
  solid_velocity_[c] = cell == FlowCell::Solid ? velocity : core::Vec3::Zero();
}

void FlowGrid::update_face(int axis, int i, int j, int k) {
  const auto& e = kAxis[static_cast<std::size_t>(axis)];
  const auto f = static_cast<std::size_t>(face_dims(axis).index(i, j, k));
  // A planar grid has no z flow: its z faces are walls.
  if (axis == 2 && planar()) {
    states_[axis][f] = FaceState::Inside;
    velocity_[axis][f] = 0.0;
    return;
  }
  const bool solid_a = cell_or_solid(i - e[0], j - e[1], k - e[2]) == FlowCell::Solid;
  const bool solid_b = cell_or_solid(i, j, k) == FlowCell::Solid;
  if (!solid_a && !solid_b) {
    states_[axis][f] = FaceState::Active;
    return;
  }
  const double va = solid_velocity(i - e[0], j - e[1], k - e[2])[axis];
  const double vb = solid_velocity(i, j, k)[axis];
  states_[axis][f] = solid_a && solid_b ? FaceState::Inside : FaceState::Prescribed;
  velocity_[axis][f] = solid_a && solid_b ? 0.5 * (va + vb) : (solid_a ? va : vb);
}

void FlowGrid::update_faces() {
  if (relabelled_ || labelling_ == 0) labelling_ = next_labelling.fetch_add(1);
  relabelled_ = false;
  for (int axis = 0; axis < 3; ++axis) {
    const FaceDims d = face_dims(axis);
    for (int k = 0; k < d.z; ++k)
      for (int j = 0; j < d.y; ++j)
        for (int i = 0; i < d.x; ++i)
          update_face(axis, i, j, k);
  }
}

void FlowGrid::set_solid_velocity(int i, int j, int k, const core::Vec3& velocity) {
  if (cell(i, j, k) != FlowCell::Solid)
    throw core::UsageError("only a solid cell of the flow grid has a velocity of its own");
  solid_velocity_[static_cast<std::size_t>(cell_index(i, j, k))] = velocity;
  for (int axis = 0; axis < 3; ++axis) {
    const auto& e = kAxis[static_cast<std::size_t>(axis)];
    update_face(axis, i, j, k);
    update_face(axis, i + e[0], j + e[1], k + e[2]);
  }
}

core::Vec3 FlowGrid::face_position(int axis, int i, int j, int k) const {
  core::Vec3 offset(i + 0.5, j + 0.5, k + 0.5);
  offset[axis] -= 0.5;
  return origin_ + h_ * offset;
}

double FlowGrid::sample(int axis, const core::Vec3& point) const {
  return sample(axis, velocity_[static_cast<std::size_t>(axis)], point);
}

double FlowGrid::sample(int axis, const std::vector<double>& v, const core::Vec3& point,
                        double* low, double* high) const {
  return FaceSampler(*this, axis)(v.data(), point, low, high);
}

core::Vec3 FlowGrid::velocity_at(const core::Vec3& point) const {
  return {sample(0, point), sample(1, point), planar() ? 0.0 : sample(2, point)};
}

core::Vec3 FlowGrid::face_velocity(int axis, int i, int j, int k) const {
  core::Vec3 velocity = core::Vec3::Zero();
  velocity[axis] = velocity_[static_cast<std::size_t>(axis)]
                            [static_cast<std::size_t>(face_dims(axis).index(i, j, k))];
  for (int other = 0; other < (planar() ? 2 : 3); ++other) {
    if (other == axis) continue;
    // The four faces of `other` around this one: its two cells (back along `axis`) and the next
    // faces along `other`.
    const FaceDims d = face_dims(other);
    const auto& v = velocity_[static_cast<std::size_t>(other)];
    std::array<int, 3> at{i, j, k};
    at[axis] -= 1;
    std::array<int, 3> next = at;
    next[other] += 1;
    std::array<int, 3> here{i, j, k}, here_next{i, j, k};
    here_next[other] += 1;
    const auto value = [&](const std::array<int, 3>& c) {
      return v[static_cast<std::size_t>(d.index(c[0], c[1], c[2]))];
    };
    velocity[other] = 0.25 * (value(at) + value(next) + value(here) + value(here_next));
  }
  return velocity;
}

double FlowGrid::max_divergence() const {
  double worst = 0.0;
  const FaceDims du = face_dims(0), dv = face_dims(1), dw = face_dims(2);
  for (int k = 0; k < nz_; ++k) {
    for (int j = 0; j < ny_; ++j) {
      for (int i = 0; i < nx_; ++i) {
        if (cell(i, j, k) != FlowCell::Fluid) continue;
        const double div = (velocity_[0][static_cast<std::size_t>(du.index(i + 1, j, k))] -
                            velocity_[0][static_cast<std::size_t>(du.index(i, j, k))]) +
                           (velocity_[1][static_cast<std::size_t>(dv.index(i, j + 1, k))] -
                            velocity_[1][static_cast<std::size_t>(dv.index(i, j, k))]) +
                           (velocity_[2][static_cast<std::size_t>(dw.index(i, j, k + 1))] -
                            velocity_[2][static_cast<std::size_t>(dw.index(i, j, k))]);
        worst = std::max(worst, std::abs(div) / h_);
      }
    }
  }
  return worst;
}

CellCoord FlowGrid::cell_of(const core::Vec3& point) const {
  const core::Vec3 local = (point - origin_) / h_;
  return {static_cast<int>(std::floor(local.x())), static_cast<int>(std::floor(local.y())),
          static_cast<int>(std::floor(local.z()))};
}

}  // namespace viscera::sim::fluid
