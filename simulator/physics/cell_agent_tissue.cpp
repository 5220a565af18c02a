#include "simulator/physics/cell_agent_tissue.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/error.h"
#include "simulator/collision/penetration_depth.h"

namespace viscera::sim {

std::vector<CellType> cell_types_of(const core::CellTissueSpec& spec) {
  std::vector<CellType> types;
  for (const auto& t : spec.types) {
    CellType c;
    c.mass = t.mass;
    c.radius = t.radius;
    c.home_stiffness = t.home_stiffness;
    c.connection_stiffness = t.connection_stiffness;
    c.damping = t.damping;
    c.collision_efficiency = t.collision_efficiency;
    c.tear_strain = t.tear_strain;
    c.yield_strain = t.yield_strain;
    types.push_back(c);
  }
  return types;
}

std::vector<CellConnection> discover_cell_connections(std::span<const core::Vec3> positions,
                                                      std::span<const CellType> types,
                                                      std::span<const int> type_of,
                                                      double neighbour_radius, int max_neighbours) {
  if (type_of.size() != positions.size()) throw core::UsageError("every cell needs a cell type");
  for (const int t : type_of) {
    if (t < 0 || t >= static_cast<int>(types.size()))
      throw core::UsageError("cell type index out of range");
  }
  std::vector<CellConnection> connections;
  if (positions.empty() || !(neighbour_radius > 0.0) || max_neighbours <= 0) return connections;
  // Bins of the radius: every neighbour of a cell lies in its bin or one of the 26 around it.
  const auto bin = [&](const core::Vec3& p) {
    return std::array<long long, 3>{static_cast<long long>(std::floor(p.x() / neighbour_radius)),
                                    static_cast<long long>(std::floor(p.y() / neighbour_radius)),
                                    static_cast<long long>(std::floor(p.z() / neighbour_radius))};
  };
  std::map<std::array<long long, 3>, std::vector<int>> bins;
  const auto n = static_cast<int>(positions.size());
  for (int i = 0; i < n; ++i)
    bins[bin(positions[static_cast<std::size_t>(i)])].push_back(i);
  std::set<std::pair<int, int>> links;
  for (int i = 0; i < n; ++i) {
    const core::Vec3& p = positions[static_cast<std::size_t>(i)];
    const auto home = bin(p);
    std::vector<std::pair<double, int>> near;
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          const auto it = bins.find({home[0] + dx, home[1] + dy, home[2] + dz});
          if (it == bins.end()) continue;
          for (const int j : it->second) {
            const double d = (positions[static_cast<std::size_t>(j)] - p).norm();
            if (j != i && d <= neighbour_radius) near.emplace_back(d, j);
          }
        }
    std::sort(near.begin(), near.end());
    const int keep = std::min<int>(max_neighbours, static_cast<int>(near.size()));
    for (int k = 0; k < keep; ++k)
      links.insert(std::minmax(i, near[static_cast<std::size_t>(k)].second));
  }
  connections.reserve(links.size());
  for (const auto& [a, b] : links) {
    const CellType& ta = types[static_cast<std::size_t>(type_of[static_cast<std::size_t>(a)])];
    const CellType& tb = types[static_cast<std::size_t>(type_of[static_cast<std::size_t>(b)])];
    const double length =
        (positions[static_cast<std::size_t>(b)] - positions[static_cast<std::size_t>(a)]).norm();
    connections.push_back(
        {a, b, length, length, 0.5 * (ta.connection_stiffness + tb.connection_stiffness),
         std::min(ta.yield_strain, tb.yield_strain), std::min(ta.tear_strain, tb.tear_strain)});
  }
  return connections;
}

std::vector<CellConnection> tear_and_yield(std::span<const core::Vec3> positions,
                                           std::vector<CellConnection>& connections) {
  const auto length_of = [&](const CellConnection& c) {
    return (positions[static_cast<std::size_t>(c.b)] - positions[static_cast<std::size_t>(c.a)])
        .norm();
  };
  std::vector<CellConnection> torn;
  std::erase_if(connections, [&](const CellConnection& c) {
    const bool tears = length_of(c) > (1.0 + c.tear_strain) * c.original_length;
    if (tears) torn.push_back(c);
    return tears;
  });
  for (auto& c : connections) {
    const double length = length_of(c);
    if (length > (1.0 + c.yield_strain) * c.rest_length)
      c.rest_length = length / (1.0 + c.yield_strain);
  }
  return torn;
}

core::Vec3 connection_force(const CellConnection& c, std::span<const core::Vec3> positions) {
  const core::Vec3 d =
      positions[static_cast<std::size_t>(c.b)] - positions[static_cast<std::size_t>(c.a)];
  const double length = d.norm();
  if (length <= 0.0) return core::Vec3::Zero();
  return (-c.stiffness * (length - c.rest_length) / length) * d;
}

CellAgentTissue::CellAgentTissue(std::vector<core::Vec3> positions, std::vector<CellType> types,
                                 std::vector<int> type_of, double neighbour_radius,
                                 int max_neighbours, bool planar)
    : types_(std::move(types)),
      type_of_(std::move(type_of)),
      home_(positions),
      position_(std::move(positions)),
      velocity_(position_.size(), core::Vec3::Zero()),
      pending_(position_.size(), core::Vec3::Zero()),
      dragged_(position_.size(), 0),
      connections_(
          discover_cell_connections(position_, types_, type_of_, neighbour_radius, max_neighbours)),
      planar_(planar) {}

void CellAgentTissue::step(double dt) {
  // Eq. 3: connection forces from the positions at the start of the step, into the pending
  // buffer, so the result does not depend on the order cells are visited.
  const std::vector<core::Vec3> springs = connection_forces();
  for (std::size_t i = 0; i < pending_.size(); ++i)
    pending_[i] += springs[i];
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
  torn_ += static_cast<int>(tear_and_yield(position_, connections_).size());
}

void CellAgentTissue::drag(int cell, const core::Vec3& position) {
  dragged_[static_cast<std::size_t>(cell)] = 1;
  position_[static_cast<std::size_t>(cell)] = position;
}

void CellAgentTissue::release(int cell) {
  dragged_[static_cast<std::size_t>(cell)] = 0;
}

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
    const core::Vec3 force = connection_force(c, position_);
    forces[c.a] -= force;
    forces[c.b] += force;
  }
  return forces;
}

}  // namespace viscera::sim
