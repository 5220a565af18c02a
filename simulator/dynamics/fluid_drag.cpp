#include "simulator/dynamics/fluid_drag.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace viscera::sim {

void FluidDrag::set(std::vector<NodeDrag> drag, const SimulationState& state) {
  for (const NodeDrag& d : drag) {
    if (d.node < 0 || static_cast<std::size_t>(d.node) >= state.node_count())
      throw core::UsageError("a fluid drag names node " + std::to_string(d.node) +
                             ", outside the state's " + std::to_string(state.node_count()));
    if (!(d.coefficient >= 0.0) || !std::isfinite(d.coefficient) || !d.fluid_velocity.allFinite())
      throw core::UsageError("the fluid drag on node " + std::to_string(d.node) +
                             " is negative or not finite");
  }
  drag_ = std::move(drag);
  start_.clear();
  start_.reserve(drag_.size());
  for (const NodeDrag& d : drag_)
    start_.push_back(state.positions[static_cast<std::size_t>(d.node)]);
}

double FluidDrag::energy(std::span<const Vec3> x) const {
  double e = 0.0;
  for (std::size_t k = 0; k < drag_.size(); ++k) {
    const NodeDrag& d = drag_[k];
    e -= d.coefficient * d.fluid_velocity.dot(x[static_cast<std::size_t>(d.node)] - start_[k]);
  }
  return e;
}

double FluidDrag::add_forces(std::span<const Vec3> x, std::span<const Vec3> v,
                             std::span<Vec3> f) const {
  if (drag_.empty()) return 0.0;
  for (const NodeDrag& d : drag_) {
    const auto n = static_cast<std::size_t>(d.node);
    f[n] += d.coefficient * (d.fluid_velocity - v[n]);
  }
  return energy(x);
}

void FluidDrag::add_damping(std::span<const Vec3> /*x*/, double scale,
                            BlockSparseMatrix& matrix) const {
  for (const NodeDrag& d : drag_)
    matrix.block(matrix.diagonal_slot(d.node)) += (scale * d.coefficient) * Mat3::Identity();
}

}  // namespace viscera::sim
