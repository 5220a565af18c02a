#include "simulator/dynamics/clip_term.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"

namespace viscera::sim {

ClipTerm::ClipTerm(std::vector<NodeReference> nodes, const Vec3& closing_direction,
                   double stiffness, const SimulationState& state, double closed_gap)
    : nodes_(std::move(nodes)),
      stiffness_(stiffness),
      current_stiffness_(stiffness),
      half_gap_(0.5 * closed_gap) {
  if (!(closed_gap >= 0.0)) throw core::UsageError("a clip's closed gap must be ≥ 0 (m)");
  if (nodes_.size() < 2) throw core::UsageError("a clip needs at least two nodes between its jaws");
  if (!(stiffness > 0.0)) throw core::UsageError("clip stiffness must be positive (N/m)");
  if (!(closing_direction.norm() > 0.0)) throw core::UsageError("clip direction must not be zero");
  direction_ = closing_direction.normalized();
  for (const NodeReference& r : nodes_)
    globals_.push_back(r.global(state));
}

Vec3 ClipTerm::centre(std::span<const Vec3> x) const {
  if (globals_.empty()) return Vec3::Zero();
  Vec3 c = Vec3::Zero();
  for (const int g : globals_)
    c += x[static_cast<std::size_t>(g)];
  return c / static_cast<double>(globals_.size());
}

double ClipTerm::gap(std::span<const Vec3> x) const {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const int g : globals_) {
    const double h = x[static_cast<std::size_t>(g)].dot(direction_);
    lo = std::min(lo, h), hi = std::max(hi, h);
  }
  return hi - lo;
}

void ClipTerm::close_over(double placed_at, double closing_time) {
  placed_at_ = placed_at;
  closing_time_ = std::max(closing_time, 0.0);
}

void ClipTerm::prepare(const SimulationState&, const StepContext& context) {
  const double closed =
      closing_time_ > 0.0 ? std::clamp((context.time - placed_at_) / closing_time_, 0.0, 1.0) : 1.0;
  current_stiffness_ = closed * stiffness_;
}

std::vector<double> ClipTerm::squeeze(std::span<const Vec3> x, double& mean) const {
  const double c = centre(x).dot(direction_);
  std::vector<double> psi;
  psi.reserve(globals_.size());
  mean = 0.0;
  for (const int g : globals_) {
    const double h = x[static_cast<std::size_t>(g)].dot(direction_) - c;
    psi.push_back(std::copysign(std::max(std::abs(h) - half_gap_, 0.0), h));
    mean += psi.back();
  }
  if (!psi.empty()) mean /= static_cast<double>(psi.size());
  return psi;
}

double ClipTerm::energy(std::span<const Vec3> x) const {
  double mean = 0.0, e = 0.0;
  for (const double p : squeeze(x, mean))
    e += 0.5 * current_stiffness_ * p * p;
  return e;
}

double ClipTerm::add_forces(std::span<const Vec3> x, std::span<const Vec3>,
                            std::span<Vec3> f) const {
  double mean = 0.0, e = 0.0;
  const std::vector<double> psi = squeeze(x, mean);
  for (std::size_t k = 0; k < psi.size(); ++k) {
    f[static_cast<std::size_t>(globals_[k])] -= (current_stiffness_ * (psi[k] - mean)) * direction_;
    e += 0.5 * current_stiffness_ * psi[k] * psi[k];
  }
  return e;
}

void ClipTerm::add_stiffness(std::span<const Vec3> x, double scale, bool,
                             BlockSparseMatrix& m) const {
  if (globals_.empty()) return;
  const double n = static_cast<double>(globals_.size());
  const double c = centre(x).dot(direction_);
  std::vector<double> active;
  double total = 0.0;
  for (const int g : globals_) {
    active.push_back(std::abs(x[static_cast<std::size_t>(g)].dot(direction_) - c) > half_gap_);
    total += active.back();
  }
  const core::Mat3 ddt = (scale * current_stiffness_) * (direction_ * direction_.transpose());
  for (std::size_t a = 0; a < globals_.size(); ++a)
    for (std::size_t b = a; b < globals_.size(); ++b) {
      const double pap = (a == b ? active[a] : 0.0) - (active[a] + active[b]) / n + total / (n * n);
      m.add_symmetric(globals_[a], globals_[b], pap * ddt);
    }
}

void ClipTerm::topology_changed(const SimulationState& state, int body) {
  refind_nodes(state, body, nodes_);
  globals_.clear();
  for (const NodeReference& r : nodes_)
    globals_.push_back(r.global(state));
}

void ClipTerm::after_step(const SimulationState& state) {
  note_positions(state, nodes_);
}

}  // namespace viscera::sim
