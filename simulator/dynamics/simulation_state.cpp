#include "simulator/dynamics/simulation_state.h"

#include <algorithm>

#include "core/error.h"

namespace viscera::sim {

int SimulationState::add_body(std::string name, std::span<const Vec3> rest,
                              std::span<const double> mass, std::span<const std::uint8_t> fixed) {
  if (mass.size() != rest.size() || (!fixed.empty() && fixed.size() != rest.size()))
    throw core::UsageError("add_body: node arrays of body " + name + " differ in length");
  const int first = static_cast<int>(positions.size());
  bodies_.push_back({std::move(name), first, static_cast<int>(rest.size())});
  for (std::size_t i = 0; i < rest.size(); ++i) {
    const bool held = !fixed.empty() && fixed[i] != 0;
    positions.push_back(rest[i]);
    rest_positions.push_back(rest[i]);
    velocities.push_back(Vec3::Zero());
    masses.push_back(mass[i]);
    inverse_masses.push_back(held || !(mass[i] > 0.0) ? 0.0 : 1.0 / mass[i]);
  }
  return static_cast<int>(bodies_.size()) - 1;
}

void SimulationState::replace_body_nodes(int b, const BodyNodeData& data) {
  const std::size_t n = data.rest.size();
  if (data.positions.size() != n || data.masses.size() != n ||
      (!data.velocities.empty() && data.velocities.size() != n) ||
      (!data.fixed.empty() && data.fixed.size() != n))
    throw core::UsageError("replace_body_nodes: node arrays of body " + body(b).name +
                           " differ in length");
  BodyNodes& range = bodies_[static_cast<std::size_t>(b)];
  const auto first = static_cast<std::ptrdiff_t>(range.first);
  const auto old_count = static_cast<std::ptrdiff_t>(range.count);
  const auto splice = [&](auto& array, const auto& values) {
    array.erase(array.begin() + first, array.begin() + first + old_count);
    array.insert(array.begin() + first, values.begin(), values.end());
  };
  splice(positions, data.positions);
  splice(rest_positions, data.rest);
  splice(velocities,
         data.velocities.empty() ? std::vector<Vec3>(n, Vec3::Zero()) : data.velocities);
  splice(masses, data.masses);
  std::vector<double> inverse(n);
  for (std::size_t i = 0; i < n; ++i) {
    const bool held = !data.fixed.empty() && data.fixed[i] != 0;
    inverse[i] = held || !(data.masses[i] > 0.0) ? 0.0 : 1.0 / data.masses[i];
  }
  splice(inverse_masses, inverse);
  const int delta = static_cast<int>(n) - range.count;
  range.count = static_cast<int>(n);
  for (std::size_t later = static_cast<std::size_t>(b) + 1; later < bodies_.size(); ++later)
    bodies_[later].first += delta;
}

int SimulationState::body_of(int node) const {
  const auto it = std::upper_bound(bodies_.begin(), bodies_.end(), node,
                                   [](int n, const BodyNodes& b) { return n < b.first; });
  return static_cast<int>(it - bodies_.begin()) - 1;
}

}  // namespace viscera::sim
