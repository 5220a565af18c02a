#include "simulator/dynamics/connection_spring_term.h"

#include "simulator/dynamics/spring_hessian.h"

namespace viscera::sim {

ConnectionSpringTerm::ConnectionSpringTerm(std::vector<ConnectionSpring> springs,
                                           const SimulationState& state)
    : springs_(std::move(springs)) {
  resolve(state);
}

void ConnectionSpringTerm::resolve(const SimulationState& state) {
  global_.clear();
  for (const ConnectionSpring& s : springs_)
    global_.push_back(
        {state.body(s.body_a).first + s.node_a, state.body(s.body_b).first + s.node_b});
}

void ConnectionSpringTerm::release(int body, std::span<const std::uint8_t> released) {
  const auto loose = [&](int b, int node) {
    return b == body && node >= 0 && static_cast<std::size_t>(node) < released.size() &&
           released[static_cast<std::size_t>(node)] != 0;
  };
  std::erase_if(springs_, [&](const ConnectionSpring& s) {
    return loose(s.body_a, s.node_a) || loose(s.body_b, s.node_b);
  });
}

void ConnectionSpringTerm::topology_changed(const SimulationState& state, int body) {
  std::vector<ConnectionSpring> kept;
  for (const ConnectionSpring& s : springs_) {
    const bool a_ok = s.body_a != body || s.node_a < state.body(body).count;
    const bool b_ok = s.body_b != body || s.node_b < state.body(body).count;
    if (a_ok && b_ok) kept.push_back(s);
  }
  springs_ = std::move(kept);
  resolve(state);
}

double ConnectionSpringTerm::energy(std::span<const Vec3> x) const {
  double energy = 0.0;
  for (std::size_t s = 0; s < springs_.size(); ++s) {
    const double stretch = (x[global_[s][1]] - x[global_[s][0]]).norm() - springs_[s].rest_length;
    energy += 0.5 * springs_[s].stiffness * stretch * stretch;
  }
  return energy;
}

double ConnectionSpringTerm::add_forces(std::span<const Vec3> x, std::span<const Vec3>,
                                        std::span<Vec3> f) const {
  double energy = 0.0;
  for (std::size_t s = 0; s < springs_.size(); ++s) {
    const auto [a, b] = global_[s];
    const Vec3 d = x[b] - x[a];
    const double length = d.norm();
    const double k = springs_[s].stiffness, l0 = springs_[s].rest_length;
    // Zero rest length: the spring is linear in d and has no direction to lose.
    const Vec3 force =
        l0 == 0.0 || length == 0.0 ? Vec3(k * d) : Vec3(k * (length - l0) / length * d);
    f[a] += force;
    f[b] -= force;
    energy += 0.5 * k * (length - l0) * (length - l0);
  }
  return energy;
}

void ConnectionSpringTerm::declare_blocks(BlockPattern& pattern) const {
  for (const auto& [a, b] : global_)
    pattern.add(a, b);
}

void ConnectionSpringTerm::add_stiffness(std::span<const Vec3> x, double scale, bool project,
                                         BlockSparseMatrix& m) const {
  for (std::size_t s = 0; s < springs_.size(); ++s) {
    const auto [a, b] = global_[s];
    const Vec3 d = x[b] - x[a];
    const double length = d.norm();
    const double k = springs_[s].stiffness, l0 = springs_[s].rest_length;
    const Mat3 h = length == 0.0
                       ? Mat3(k * Mat3::Identity())
                       : radial_hessian(d / length, length, k * (length - l0), k, project);
    add_pair_block(m, a, b, h, scale);
  }
}

}  // namespace viscera::sim
