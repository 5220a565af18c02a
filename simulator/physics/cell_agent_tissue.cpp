#include "simulator/physics/cell_agent_tissue.h"

#include <algorithm>
#include <set>

#include "core/error.h"
#include "simulator/collision/penetration_depth.h"

namespace viscera::sim {

CellAgentTissue::CellAgentTissue(std::vector<core::Vec3> positions, std::vector<CellType> types,
                                 std::vector<int> type_of, double neighbour_radius, int max_neighbours, bool planar)
    : types_(std::move(types)),
      type_of_(std::move(type_of)),
      home_(positions),
      position_(std::move(positions)),
      velocity_(position_.size(), core::Vec3::Zero()),
      pending_(position_.size(), core::Vec3::Zero()),
      dragged_(position_.size(), 0),
      planar_(planar) {
  if (type_of_.size() != position_.size()) throw core::UsageError("every cell needs a cell type");
  for (const int t : type_of_) {
    if (t < 0 || t >= static_cast<int>(types_.size())) throw core::UsageError("cell type index out of range");
  }
  discover_neighbours(neighbour_radius, max_neighbours);
}

void CellAgentTissue::discover_neighbours(double radius, int max_neighbours) {
  // Each cell picks its nearest cells within the radius (ties broken by index for determinism);
  // a connection exists when either side picked the other.
  std::set<std::pair<int, int>> links;
  const auto n = static_cast<int>(position_.size());
  for (int i = 0; i < n; ++i) {
    std::vector<std::pair<double, int>> near;
    for (int j = 0; j < n; ++j) {
      const double d = (position_[j] - position_[i]).norm();
      if (j != i && d <= radius) near.emplace_back(d, j);
    }
    std::sort(near.begin(), near.end());
    for (int k = 0; k < std::min<int>(max_neighbours, static_cast<int>(near.size())); ++k) {
      links.insert(std::minmax(i, near[k].second));
    }
  }
  for (const auto& [a, b] : links) {
    const CellType& ta = types_[type_of_[a]];
    const CellType& tb = types_[type_of_[b]];
    const double length = (position_[b] - position_[a]).norm();
    connections_.push_back({a, b, length, length, 0.5 * (ta.connection_stiffness + tb.connection_stiffness),
                            std::min(ta.yield_strain, tb.yield_strain), std::min(ta.tear_strain, tb.tear_strain)});
  }
}

void CellAgentTissue::step(double dt) {
  // Eq. 3: connection forces from the positions at the start of the step, into the pending
  // buffer, so the result does not depend on the order cells are visited.
  const std::vector<core::Vec3> springs = connection_forces();
  for (std::size_t i = 0; i < pending_.size(); ++i) pending_[i] += springs[i];
  // Eq. 8–9: elastic collisions between cells closer than their radii, as a rebound force
  // ½ k_collision m |v_rel|² along the line of centres, added to the pending buffer.
  for (const auto& c : connections_) {
    const core::Vec3 d = position_[c.b] - position_[c.a];
    const double length = d.norm();
    const CellType& ta = types_[type_of_[c.a]];
    const CellType& tb = types_[type_of_[c.b]];
    if (length <= 0.0 || length >= ta.radius + tb.radius) continue;
    const core::Vec3 normal = d / length;
    const double approach = (velocity_[c.a] - velocity_[c.b]).dot(normal);
    if (approach <= 0.0) continue;
    const double mass = 0.5 * (ta.mass + tb.mass);
    const double efficiency = 0.5 * (ta.collision_efficiency + tb.collision_efficiency);
    const core::Vec3 rebound = (0.5 * efficiency * mass * approach * approach) * normal;
    pending_[c.a] -= rebound;
    pending_[c.b] += rebound;
  }
  // Eq. 4–7 per cell.
  for (std::size_t i = 0; i < position_.size(); ++i) {
    const CellType& type = types_[type_of_[i]];
    if (dragged_[i]) {
      velocity_[i].setZero();
    } else {
      const core::Vec3 force = pending_[i] + type.home_stiffness * (home_[i] - position_[i]);
      const core::Vec3 acceleration = force / type.mass;
      velocity_[i] += dt * acceleration - type.damping * velocity_[i];
      if (planar_) velocity_[i].z() = 0.0;
      position_[i] += dt * velocity_[i];
    }
    pending_[i].setZero();
  }
  // Tearing and plasticity on the new positions.
  const auto before = connections_.size();
  std::erase_if(connections_, [&](const CellConnection& c) {
    return (position_[c.b] - position_[c.a]).norm() > (1.0 + c.tear_strain) * c.original_length;
  });
  torn_ += static_cast<int>(before - connections_.size());
  for (auto& c : connections_) {
    const double length = (position_[c.b] - position_[c.a]).norm();
    if (length > (1.0 + c.yield_strain) * c.rest_length) c.rest_length = length / (1.0 + c.yield_strain);
  }
}

void CellAgentTissue::drag(int cell, const core::Vec3& position) {
  dragged_[static_cast<std::size_t>(cell)] = 1;
  position_[static_cast<std::size_t>(cell)] = position;
}

void CellAgentTissue::release(int cell) { dragged_[static_cast<std::size_t>(cell)] = 0; }

int CellAgentTissue::cut(const core::Vec3& a, const core::Vec3& b, const core::Vec3& c) {
  const auto before = connections_.size();
  std::erase_if(connections_, [&](const CellConnection& link) {
    return segment_triangle_intersection(position_[link.a], position_[link.b], a, b, c) >= 0.0;
  });
  return static_cast<int>(before - connections_.size());
}

std::vector<core::Vec3> CellAgentTissue::connection_forces() const {
  std::vector<core::Vec3> forces(position_.size(), core::Vec3::Zero());
  for (const auto& c : connections_) {
    const core::Vec3 d = position_[c.b] - position_[c.a];
    const double length = d.norm();
    if (length <= 0.0) continue;
    const core::Vec3 force = (c.stiffness * (length - c.rest_length) / length) * d;
    forces[c.a] += force;
    forces[c.b] -= force;
  }
  return forces;
}

}  // namespace viscera::sim
