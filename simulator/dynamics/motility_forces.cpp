#include "simulator/dynamics/motility_forces.h"

#include "core/error.h"

namespace viscera::sim {

MotilityForces::MotilityForces(std::shared_ptr<const BodyModel> model, const SimulationState& state,
                               const core::MotilitySpec& spec, std::uint64_t seed, std::string id)
    : BodyTerm(std::move(model)), spec_(spec), seed_(seed), id_(std::move(id)) {
  initialise(state);
}

void MotilityForces::build(const SimulationState& state, int first) {
  first_ = first;
  const auto rest = state.range(state.rest_positions, model().body);
  try {
    motility_.emplace(spec_, std::vector<Vec3>(rest.begin(), rest.end()), seed_);
  } catch (const core::UsageError& e) {
    throw core::InputError("motility \"" + id_ + "\" on \"" + model().name + "\": " + e.reason(),
                           {"", "", id_});
  }
  const BodyModel& body = model();
  if (body.mesh.tets.empty()) {
    throw core::InputError(
        "motility \"" + id_ + "\" targets \"" + body.name + "\", which has no tets to move",
        {"", "", id_});
  }
  const auto n = rest.size();
  stiffness_ = node_distance_stiffness(body, rest);
  for (std::size_t i = 0; i < n; ++i) {
    const bool held = state.inverse_masses[static_cast<std::size_t>(first) + i] == 0.0;
    stiffness_[i] = held ? 0.0 : kStiffnessFactor * stiffness_[i];
  }
  anchors_ = motility_->positions(state.time);
}

void MotilityForces::prepare(const SimulationState& /*state*/, const StepContext& context) {
  anchors_ = motility_->positions(context.time + context.h);
}

double MotilityForces::energy(std::span<const Vec3> x) const {
  double e = 0.0;
  for (std::size_t i = 0; i < anchors_.size(); ++i) {
    if (stiffness_[i] == 0.0) continue;
    e +=
        0.5 * stiffness_[i] * (x[static_cast<std::size_t>(first_) + i] - anchors_[i]).squaredNorm();
  }
  return e;
}

double MotilityForces::add_forces(std::span<const Vec3> x, std::span<const Vec3> /*v*/,
                                  std::span<Vec3> f) const {
  double e = 0.0;
  for (std::size_t i = 0; i < anchors_.size(); ++i) {
    if (stiffness_[i] == 0.0) continue;
    const auto g = static_cast<std::size_t>(first_) + i;
    const Vec3 stretch = x[g] - anchors_[i];
    f[g] -= stiffness_[i] * stretch;
    e += 0.5 * stiffness_[i] * stretch.squaredNorm();
  }
  return e;
}

void MotilityForces::add_stiffness(std::span<const Vec3> /*x*/, double scale, bool /*project*/,
                                   BlockSparseMatrix& matrix) const {
  for (std::size_t i = 0; i < anchors_.size(); ++i) {
    if (stiffness_[i] == 0.0) continue;
    const int g = first_ + static_cast<int>(i);
    matrix.block(matrix.diagonal_slot(g)) += (scale * stiffness_[i]) * Mat3::Identity();
  }
}

}  // namespace viscera::sim
