#include "simulator/dynamics/impact_forces.h"

#include "core/error.h"

namespace viscera::sim {

void ImpactForces::set(std::vector<std::pair<int, Vec3>> forces, const SimulationState& state) {
  for (const auto& [node, force] : forces) {
    if (node < 0 || static_cast<std::size_t>(node) >= state.node_count())
      throw core::UsageError("an impact force names node " + std::to_string(node) +
                             ", outside the state's " + std::to_string(state.node_count()));
  }
  forces_ = std::move(forces);
  start_.clear();
  start_.reserve(forces_.size());
  for (const auto& [node, force] : forces_)
    start_.push_back(state.positions[static_cast<std::size_t>(node)]);
}

Vec3 ImpactForces::total() const {
  Vec3 sum = Vec3::Zero();
  for (const auto& [node, force] : forces_)
    sum += force;
  return sum;
}

double ImpactForces::energy(std::span<const Vec3> x) const {
  double e = 0.0;
  for (std::size_t k = 0; k < forces_.size(); ++k)
    e -= forces_[k].second.dot(x[static_cast<std::size_t>(forces_[k].first)] - start_[k]);
  return e;
}

double ImpactForces::add_forces(std::span<const Vec3> x, std::span<const Vec3>,
                                std::span<Vec3> f) const {
  if (forces_.empty()) return 0.0;
  for (const auto& [node, force] : forces_)
    f[static_cast<std::size_t>(node)] += force;
  return energy(x);
}

}  // namespace viscera::sim
