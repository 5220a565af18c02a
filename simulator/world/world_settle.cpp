#include <algorithm>
#include <cmath>
#include <memory>

#include "simulator/dynamics/attachment_term.h"
#include "simulator/dynamics/authored_terms.h"
#include "simulator/dynamics/backward_euler.h"
#include "simulator/dynamics/connection_spring_term.h"
#include "simulator/dynamics/pulse_waves.h"
#include "simulator/world/world.h"

namespace viscera::sim {
std::vector<std::uint8_t> World::held_nodes(int body) const {
  const auto inverse = state_.range(state_.inverse_masses, body);
  std::vector<std::uint8_t> held(inverse.size(), 0);
  for (std::size_t i = 0; i < inverse.size(); ++i)
    held[i] = inverse[i] == 0.0 ? 1 : 0;
  const auto hold = [&](int node) {
    if (node >= 0 && static_cast<std::size_t>(node) < held.size())
      held[static_cast<std::size_t>(node)] = 1;
  };
  for (const auto& term : terms_) {
    if (const auto* attachments = dynamic_cast<const AttachmentTerm*>(term.get())) {
      for (const Attachment& a : attachments->attachments())
        if (a.body == body && a.host != body) hold(a.node);
    } else if (const auto* springs = dynamic_cast<const ConnectionSpringTerm*>(term.get())) {
      for (const ConnectionSpring& s : springs->springs()) {
        if (s.body_a == body && s.body_b != body) hold(s.node_a);
        if (s.body_b == body && s.body_a != body) hold(s.node_b);
      }
    }
  }
  return held;
}

World::Settling World::settle(double h, int max_steps, double tolerance) {
  Settling result;
  if (state_.node_count() == 0) return result;
  for (int b = 0; b < static_cast<int>(state_.bodies().size()); ++b) {
    const auto held = held_nodes(b);
    if (std::find(held.begin(), held.end(), std::uint8_t{1}) == held.end()) return result;
  }
  auto* implicit = dynamic_cast<BackwardEuler*>(integrator_.get());
  refresh_integrator();
  std::vector<ForceTerm*> terms = term_pointers();
  const double clock = state_.time;
  // The steps' clock: an explicit world's motility holds its anchors where they are at the
  // session's start (MotilityForces pulls towards the rest shape moved to time + h).
  double step_clock = clock;
  // An explicit world (the KisMo nets of a laparoscopy) settles with a backward Euler of its
  // own, under every term but the pulse — an impulsive load, zero between the wave fronts, so
  // the vessels' rest between beats is the passive one — and with the organs' motility at the
  // session's start. Its driven islands move from there, and its undriven ones (the veins)
  // start at rest and fall asleep instead of ringing down from the authored shape for seconds.
  std::unique_ptr<BackwardEuler> descent_integrator;
  if (implicit == nullptr) {
    std::erase_if(terms, [](const ForceTerm* t) { return dynamic_cast<const PulseWaves*>(t); });
    descent_integrator = std::make_unique<BackwardEuler>();
    descent_integrator->topology_changed(state_, terms);
    implicit = descent_integrator.get();
    step_clock = clock - h;
  } else if (drives_bodies(terms_)) {
    return result;  // motility or a pulse: no rest to settle to
  }
  // The steps are a descent in pseudo-time, not a motion: only where they end matters, so each
  // takes at most kSettleNewtonIterations Newton iterations of at most kSettleCgIterations CG
  // iterations instead of converging (at 50 ms the mass no longer conditions the stiffness for
  // block Jacobi). Where they end is checked by force: at rest needs the largest nodal force
  // residual within the integrator's tolerance as well as no node moving.
  const NewtonSettings session = implicit->settings();
  NewtonSettings descent = session;
  descent.max_newton_iterations = std::min(session.max_newton_iterations, kSettleNewtonIterations);
  descent.max_cg_iterations = std::min(session.max_cg_iterations, kSettleCgIterations);
  implicit->set_settings(descent);
  while (result.steps < max_steps && !result.at_rest) {
    std::fill(state_.velocities.begin(), state_.velocities.end(), Vec3::Zero());
    const StepStatistics step = implicit->step(state_, terms, StepContext{step_clock, h, 0});
    ++result.steps;
    double fastest = 0.0;
    for (const Vec3& v : state_.velocities)
      fastest = std::max(fastest, v.squaredNorm());
    result.last_move = std::sqrt(fastest) * h;
    result.at_rest = result.last_move < tolerance && step.residual <= session.residual_tolerance;
  }
  implicit->set_settings(session);
  std::fill(state_.velocities.begin(), state_.velocities.end(), Vec3::Zero());
  state_.time = clock;
  check_state();
  // At rest and nothing drives it: the session starts asleep (what kCalmStepsToSleep calm
  // steps would conclude), and wakes when the instrument first touches.
  if (result.at_rest && sleep_threshold_ > 0.0 && tolerance <= sleep_threshold_ && !driven()) {
    asleep_ = true;
    calm_steps_ = kCalmStepsToSleep;
  }
  return result;
}

}  // namespace viscera::sim
