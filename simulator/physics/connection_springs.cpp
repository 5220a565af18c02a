#include "simulator/physics/connection_springs.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "core/error.h"

namespace viscera::sim {
namespace {

int body_index(const std::vector<DeformableBody>& bodies, const std::string& id,
               const std::string& pointer) {
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (bodies[b].name() == id) return static_cast<int>(b);
  throw core::InputError("connected object \"" + id + "\" has no simulated body",
                         {"", pointer, id});
}

void check_node(const DeformableBody& body, int node, const std::string& pointer) {
  if (node < 0 || static_cast<std::size_t>(node) >= body.node_count()) {
    throw core::InputError("node " + std::to_string(node) + " is not a node of body \"" +
                               body.name() + "\" (" + std::to_string(body.node_count()) + " nodes)",
                           {"", pointer, body.name()});
  }
}

}  // namespace

ConnectionSprings::ConnectionSprings(const core::Scenario& scenario,
                                     const std::vector<DeformableBody>& bodies) {
  std::map<std::pair<int, int>, double> stiffness_at_node;
  for (std::size_t c = 0; c < scenario.connections.size(); ++c) {
    const core::Connection& connection = scenario.connections[c];
    const std::string pointer = "/scenario/connections/" + std::to_string(c);
    if (!(connection.stiffness > 0.0) || !std::isfinite(connection.stiffness)) {
      throw core::InputError("connection stiffness must be positive and finite",
                             {"", pointer + "/stiffness", connection.id});
    }
    const int a = body_index(bodies, connection.object_a, pointer + "/object_a");
    const int b = body_index(bodies, connection.object_b, pointer + "/object_b");
    for (std::size_t p = 0; p < connection.node_pairs.size(); ++p) {
      const auto [node_a, node_b] = connection.node_pairs[p];
      const std::string pair_pointer = pointer + "/node_pairs/" + std::to_string(p);
      check_node(bodies[static_cast<std::size_t>(a)], node_a, pair_pointer + "/0");
      check_node(bodies[static_cast<std::size_t>(b)], node_b, pair_pointer + "/1");
      const core::Vec3& rest_a = bodies[static_cast<std::size_t>(a)].rest_positions()[node_a];
      const core::Vec3& rest_b = bodies[static_cast<std::size_t>(b)].rest_positions()[node_b];
      springs_.push_back({a, node_a, b, node_b, connection.stiffness, (rest_b - rest_a).norm()});
      stiffness_at_node[{a, node_a}] += connection.stiffness;
      stiffness_at_node[{b, node_b}] += connection.stiffness;
    }
  }
  for (const auto& [node, stiffness] : stiffness_at_node)
    max_node_stiffness_ = std::max(max_node_stiffness_, stiffness);
}

void ConnectionSprings::apply(std::vector<DeformableBody>& bodies) const {
  for (const ConnectionSpring& spring : springs_) {
    DeformableBody& body_a = bodies[static_cast<std::size_t>(spring.body_a)];
    DeformableBody& body_b = bodies[static_cast<std::size_t>(spring.body_b)];
    const core::Vec3 d = body_b.positions()[spring.node_b] - body_a.positions()[spring.node_a];
    const double length = d.norm();
    // Zero rest length: the spring is linear in d and has no direction to lose.
    const core::Vec3 force =
        spring.rest_length == 0.0 || length == 0.0
            ? core::Vec3(spring.stiffness * d)
            : core::Vec3(spring.stiffness * (length - spring.rest_length) / length * d);
    body_a.add_force(spring.node_a, force);
    body_b.add_force(spring.node_b, -force);
  }
}

void ConnectionSprings::add_linearised_terms(RankOneSystem& stiffness,
                                             std::span<const int> offsets) const {
  for (const ConnectionSpring& spring : springs_) {
    const int nodes[2] = {offsets[static_cast<std::size_t>(spring.body_a)] + spring.node_a,
                          offsets[static_cast<std::size_t>(spring.body_b)] + spring.node_b};
    for (int axis = 0; axis < 3; ++axis) {
      const core::Vec3 e = core::Vec3::Unit(axis);
      const core::Vec3 gradient[2] = {-e, e};
      stiffness.add_term(nodes, gradient, spring.stiffness);
    }
  }
}

void ConnectionSprings::add_node_stiffness(int body, std::span<double> node_stiffness) const {
  for (const ConnectionSpring& spring : springs_) {
    if (spring.body_a == body) node_stiffness[static_cast<std::size_t>(spring.node_a)] += 2.0 * spring.stiffness;
    if (spring.body_b == body) node_stiffness[static_cast<std::size_t>(spring.node_b)] += 2.0 * spring.stiffness;
  }
}

double ConnectionSprings::energy(const std::vector<DeformableBody>& bodies) const {
  double energy = 0.0;
  for (const ConnectionSpring& spring : springs_) {
    const core::Vec3 d =
        bodies[static_cast<std::size_t>(spring.body_b)].positions()[spring.node_b] -
        bodies[static_cast<std::size_t>(spring.body_a)].positions()[spring.node_a];
    const double stretch = d.norm() - spring.rest_length;
    energy += 0.5 * spring.stiffness * stretch * stretch;
  }
  return energy;
}

}  // namespace viscera::sim
