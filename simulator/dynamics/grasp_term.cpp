#include "simulator/dynamics/grasp_term.h"

#include <algorithm>

#include "core/error.h"

namespace viscera::sim {

GraspTerm::GraspTerm(double stiffness) : stiffness_(stiffness) {
  if (!(stiffness > 0.0)) throw core::UsageError("grasper stiffness must be positive (N/m)");
}

void GraspTerm::refresh_globals(const SimulationState& state) {
  globals_.clear();
  for (const NodeReference& r : held_)
    globals_.push_back(r.global(state));
}

void GraspTerm::hold(const SimulationState& state, std::vector<NodeReference> nodes,
                     const Vec3& tip, const core::Mat3& rotation) {
  held_ = std::move(nodes);
  tip_ = tip;
  rotation_ = rotation;
  refresh_globals(state);
  offsets_.clear();
  for (const int g : globals_)
    offsets_.push_back(rotation.transpose() * (state.positions[static_cast<std::size_t>(g)] - tip));
}

void GraspTerm::move_jaws(const Vec3& tip, const core::Mat3& rotation) {
  tip_ = tip;
  rotation_ = rotation;
}

void GraspTerm::topology_changed(const SimulationState& state, int body) {
  // Held nodes are found again by their rest and last positions; their offsets stay with them.
  const std::vector<Vec3> before = std::move(offsets_);
  offsets_.clear();
  for (const std::size_t k : refind_nodes(state, body, held_))
    offsets_.push_back(before[k]);
  refresh_globals(state);
}

void GraspTerm::after_step(const SimulationState& state) {
  note_positions(state, held_);
}

double GraspTerm::energy(std::span<const Vec3> x) const {
  double e = 0.0;
  for (std::size_t k = 0; k < globals_.size(); ++k)
    e += 0.5 * stiffness_ * (x[static_cast<std::size_t>(globals_[k])] - target(k)).squaredNorm();
  return e;
}

double GraspTerm::add_forces(std::span<const Vec3> x, std::span<const Vec3>,
                             std::span<Vec3> f) const {
  double e = 0.0;
  for (std::size_t k = 0; k < globals_.size(); ++k) {
    const auto i = static_cast<std::size_t>(globals_[k]);
    const Vec3 d = x[i] - target(k);
    f[i] -= stiffness_ * d;
    e += 0.5 * stiffness_ * d.squaredNorm();
  }
  return e;
}

void GraspTerm::add_stiffness(std::span<const Vec3>, double scale, bool,
                              BlockSparseMatrix& m) const {
  for (const int g : globals_)
    m.block(m.diagonal_slot(g)) += (scale * stiffness_) * core::Mat3::Identity();
}

Vec3 GraspTerm::force_on_jaws(std::span<const Vec3> x) const {
  Vec3 sum = Vec3::Zero();
  for (std::size_t k = 0; k < globals_.size(); ++k)
    sum += stiffness_ * (x[static_cast<std::size_t>(globals_[k])] - target(k));
  return sum;
}

double GraspTerm::largest_node_force(std::span<const Vec3> x) const {
  double largest = 0.0;
  for (std::size_t k = 0; k < globals_.size(); ++k)
    largest = std::max(largest,
                       stiffness_ * (x[static_cast<std::size_t>(globals_[k])] - target(k)).norm());
  return largest;
}

int GraspTerm::tear_out(std::span<const Vec3> x, double limit) {
  int torn = 0;
  std::size_t kept = 0;
  for (std::size_t k = 0; k < globals_.size(); ++k) {
    if (stiffness_ * (x[static_cast<std::size_t>(globals_[k])] - target(k)).norm() > limit) {
      ++torn;
      continue;
    }
    held_[kept] = held_[k], offsets_[kept] = offsets_[k], globals_[kept] = globals_[k];
    ++kept;
  }
  held_.resize(kept), offsets_.resize(kept), globals_.resize(kept);
  return torn;
}

}  // namespace viscera::sim
