#include "simulator/dynamics/hydrometra_forces.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace viscera::sim {

HydrometraForces::HydrometraForces(std::shared_ptr<const BodyModel> model,
                                   const SimulationState& state, const core::SceneObject& object)
    : BodyTerm(std::move(model)), states_(object.hydrometra), cavity_(cavity_surface(object)) {
  if (states_.empty() || cavity_.empty())
    throw core::InputError("object " + object.id + " has no hydrometra states or no cavity",
                           {"", "", object.id});
  for (int k = 0; k + 1 < states_.state_count(); ++k) {
    const auto a = states_.state(k);
    const auto b = states_.state(k + 1);
    double largest = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i)
      largest = std::max(largest, (b[i] - a[i]).norm());
    const double dp = states_.pressures[static_cast<std::size_t>(k) + 1] -
                      states_.pressures[static_cast<std::size_t>(k)];
    slope_ = std::max(slope_, largest / dp);
  }
  initialise(state);
}

void HydrometraForces::build(const SimulationState& state, int first) {
  first_ = first;
  const auto rest = state.range(state.rest_positions, model().body);
  const BodyModel& body = model();
  if (static_cast<int>(rest.size()) != states_.node_count)
    throw core::InputError("the hydrometra states of " + body.name + " have " +
                               std::to_string(states_.node_count) + " nodes, its body " +
                               std::to_string(rest.size()),
                           {"", "", body.name});
  rest_.assign(rest.begin(), rest.end());
  const std::size_t n = rest.size();
  stiffness_ = node_distance_stiffness(body, rest);
  for (std::size_t i = 0; i < n; ++i) {
    const bool held = state.inverse_masses[static_cast<std::size_t>(first) + i] == 0.0;
    stiffness_[i] = held ? 0.0 : kStiffnessFactor * stiffness_[i];
  }
  displacement_.assign(n, Vec3::Zero());
  loads_.assign(n, Vec3::Zero());
  targets_.clear();  // prepared again at the next step
}

double HydrometraForces::clamped(double pressure) const {
  if (!(pressure > states_.pressures.front())) return states_.pressures.front();
  return std::min(pressure, states_.pressures.back());
}

double HydrometraForces::set_pressure(double pressure) {
  pressure_ = pressure;
  return slope_ * std::abs(clamped(pressure) - clamped(prepared_pressure_));
}

void HydrometraForces::prepare(const SimulationState& /*state*/, const StepContext& /*context*/) {
  if (!targets_.empty() && pressure_ == prepared_pressure_) return;
  prepared_pressure_ = pressure_;
  core::interpolate_hydrometra(states_, pressure_, displacement_);
  targets_.resize(rest_.size());
  for (std::size_t i = 0; i < rest_.size(); ++i)
    targets_[i] = rest_[i] + displacement_[i];
  std::fill(loads_.begin(), loads_.end(), Vec3::Zero());
  // The load of the pressure the shape is the equilibrium of: clamped like the states.
  add_pressure_load(cavity_, clamped(pressure_), targets_, loads_);
  for (std::size_t i = 0; i < loads_.size(); ++i)
    if (stiffness_[i] == 0.0) loads_[i].setZero();  // held nodes
}

double HydrometraForces::energy(std::span<const Vec3> x) const {
  double e = 0.0;
  if (targets_.empty()) return e;
  for (std::size_t i = 0; i < stiffness_.size(); ++i) {
    if (stiffness_[i] == 0.0) continue;
    const Vec3& xi = x[static_cast<std::size_t>(first_) + i];
    e += 0.5 * stiffness_[i] * (xi - targets_[i]).squaredNorm() - loads_[i].dot(xi);
  }
  return e;
}

double HydrometraForces::add_forces(std::span<const Vec3> x, std::span<const Vec3> /*v*/,
                                    std::span<Vec3> f) const {
  double e = 0.0;
  if (targets_.empty()) return e;
  for (std::size_t i = 0; i < stiffness_.size(); ++i) {
    if (stiffness_[i] == 0.0) continue;
    const std::size_t g = static_cast<std::size_t>(first_) + i;
    const Vec3 stretch = x[g] - targets_[i];
    f[g] += loads_[i] - stiffness_[i] * stretch;
    e += 0.5 * stiffness_[i] * stretch.squaredNorm() - loads_[i].dot(x[g]);
  }
  return e;
}

void HydrometraForces::add_stiffness(std::span<const Vec3> /*x*/, double scale, bool /*project*/,
                                     BlockSparseMatrix& matrix) const {
  for (std::size_t i = 0; i < stiffness_.size(); ++i) {
    if (stiffness_[i] == 0.0) continue;
    const int g = first_ + static_cast<int>(i);
    matrix.block(matrix.diagonal_slot(g)) += (scale * stiffness_[i]) * Mat3::Identity();
  }
}

}  // namespace viscera::sim
