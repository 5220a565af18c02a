#include "simulator/dynamics/gravity_term.h"

namespace viscera::sim {

GravityTerm::GravityTerm(const Vec3& gravity, const SimulationState& state) : gravity_(gravity) {
  topology_changed(state, -1);
}

void GravityTerm::topology_changed(const SimulationState& state, int) {
  mass_ = state.masses;
  rest_ = state.rest_positions;
}

double GravityTerm::energy(std::span<const Vec3> x) const {
  double e = 0.0;
  for (std::size_t i = 0; i < mass_.size(); ++i)
    e -= mass_[i] * gravity_.dot(x[i] - rest_[i]);
  return e;
}

double GravityTerm::add_forces(std::span<const Vec3> x, std::span<const Vec3>,
                               std::span<Vec3> f) const {
  if (gravity_.squaredNorm() == 0.0) return 0.0;
  double e = 0.0;  // as energy(x), in the same order, in the same pass
  for (std::size_t i = 0; i < mass_.size(); ++i) {
    f[i] += mass_[i] * gravity_;
    e -= mass_[i] * gravity_.dot(x[i] - rest_[i]);
  }
  return e;
}

void GravityTerm::add_node_forces(std::span<const int> nodes, std::span<const Vec3>,
                                  std::span<const Vec3>, std::span<Vec3> f) const {
  if (gravity_.squaredNorm() == 0.0) return;
  for (const int node : nodes) {
    const auto i = static_cast<std::size_t>(node);
    f[i] += mass_[i] * gravity_;
  }
}

}  // namespace viscera::sim
