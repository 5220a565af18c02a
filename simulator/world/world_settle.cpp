#include <algorithm>
#include <cmath>

#include "simulator/dynamics/attachment_term.h"
#include "simulator/dynamics/authored_terms.h"
#include "simulator/dynamics/backward_euler.h"
#include "simulator/dynamics/connection_spring_term.h"
#include "simulator/world/world.h"

namespace viscera::sim {
namespace {

/// Whether every body has a fixed node or is tied to another body by an attachment or a
/// connection spring.
bool every_body_held(const SimulationState& state,
                     const std::vector<std::unique_ptr<ForceTerm>>& terms) {
  const int bodies = static_cast<int>(state.bodies().size());
  std::vector<char> held(static_cast<std::size_t>(bodies), 0);
  for (int b = 0; b < bodies; ++b) {
    const auto inverse = state.range(state.inverse_masses, b);
    held[static_cast<std::size_t>(b)] =
        std::any_of(inverse.begin(), inverse.end(), [](double w) { return w == 0.0; });
  }
  for (const auto& term : terms) {
    if (const auto* a = dynamic_cast<const AttachmentTerm*>(term.get())) {
      for (const Attachment& attachment : a->attachments())
        if (attachment.host != attachment.body) held[static_cast<std::size_t>(attachment.body)] = 1;
    } else if (const auto* c = dynamic_cast<const ConnectionSpringTerm*>(term.get())) {
      for (const ConnectionSpring& spring : c->springs()) {
        if (spring.body_a == spring.body_b) continue;
        held[static_cast<std::size_t>(spring.body_a)] = 1;
        held[static_cast<std::size_t>(spring.body_b)] = 1;
      }
    }
  }
  return std::all_of(held.begin(), held.end(), [](char h) { return h != 0; });
}

}  // namespace

World::Settling World::settle(double h, int max_steps, double tolerance) {
  Settling result;
  if (dynamic_cast<const BackwardEuler*>(integrator_.get()) == nullptr) return result;
  if (state_.node_count() == 0 || !every_body_held(state_, terms_)) return result;
  if (drives_bodies(terms_)) return result;  // motility or a pulse: no rest to settle to
  const double clock = state_.time;
  const std::vector<ForceTerm*> terms = term_pointers();
  while (result.steps < max_steps && !result.at_rest) {
    std::fill(state_.velocities.begin(), state_.velocities.end(), Vec3::Zero());
    integrator_->step(state_, terms, StepContext{clock, h, 0});
    ++result.steps;
    double fastest = 0.0;
    for (const Vec3& v : state_.velocities)
      fastest = std::max(fastest, v.squaredNorm());
    result.last_move = std::sqrt(fastest) * h;
    result.at_rest = result.last_move < tolerance;
  }
  std::fill(state_.velocities.begin(), state_.velocities.end(), Vec3::Zero());
  state_.time = clock;
  check_state();
  return result;
}

}  // namespace viscera::sim
