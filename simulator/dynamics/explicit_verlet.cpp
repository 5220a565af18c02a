#include "simulator/dynamics/explicit_verlet.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

#include "simulator/physics/stable_step.h"

namespace viscera::sim {

std::vector<double> ExplicitVerlet::island_stable_steps() const {
  std::vector<double> out;
  for (const Island& island : islands_)
    out.push_back(island.stable_step);
  return out;
}

std::vector<int> ExplicitVerlet::needed_substeps(double h, std::span<const char> far) const {
  std::vector<int> out;
  for (std::size_t g = 0; g < islands_.size(); ++g) {
    const double stable =
        !far.empty() && far[g] != 0 ? islands_[g].far_stable_step : islands_[g].stable_step;
    const bool needs = std::isfinite(stable) && !islands_[g].asleep;
    out.push_back(needs ? std::max(1, static_cast<int>(std::ceil(h / stable - 1e-12))) : 1);
  }
  return out;
}

std::vector<char> ExplicitVerlet::islands_out_of_reach(const SimulationState& state,
                                                       std::span<ForceTerm* const> reaching) const {
  std::vector<core::BoundingBox> reach;
  for (ForceTerm* t : reaching)
    reach.push_back(t->reach());
  std::vector<char> far(islands_.size(), 1);
  for (std::size_t g = 0; g < islands_.size(); ++g) {
    core::BoundingBox box;
    for (const int i : islands_[g].nodes)
      box.add(state.positions[static_cast<std::size_t>(i)]);
    for (const core::BoundingBox& r : reach) {
      const bool overlap =
          (box.min.array() <= r.max.array()).all() && (r.min.array() <= box.max.array()).all();
      if (overlap) far[g] = 0;
    }
  }
  return far;
}

namespace {

/// The smallest of 1, 2, 3, 4, 6, 8, 12, 16, 24, … (2^k and 3·2^k) not below `n`: a count of
/// fine sub-steps with many divisors for the slower islands.
int rich_count(int n) {
  for (int p = 1;; p *= 2) {
    if (p >= n) return p;
    if (3 * p / 2 >= n && p >= 2) return 3 * p / 2;
  }
}

/// The smallest divisor of `fine` not below `need`.
int divisor_at_least(int fine, int need) {
  for (int d = std::max(1, need); d < fine; ++d)
    if (fine % d == 0) return d;
  return fine;
}

}  // namespace

ExplicitVerlet::Plan ExplicitVerlet::plan(const std::vector<int>& need) const {
  const int most = need.empty() ? 1 : *std::max_element(need.begin(), need.end());
  if (!every_node_in_an_island_ ||
      std::all_of(need.begin(), need.end(), [&](int k) { return k == most; }))
    return {most, {}};
  Plan out{rich_count(most), {}};
  for (const int k : need)
    out.strides.push_back(out.fine / divisor_at_least(out.fine, k));
  return out;
}

int ExplicitVerlet::substeps(double h) const {
  return plan(needed_substeps(h)).fine;
}

StepStatistics ExplicitVerlet::step(SimulationState& state, std::span<ForceTerm* const> terms,
                                    const StepContext& context) {
  if (!ready_ || forces_.size() != state.node_count()) topology_changed(state, terms);
  StepStatistics stats;
  // Terms whose worst case acts only within reach are prepared for the first sub-step before
  // the plan (where they act this step decides which islands need their stiffness), and not
  // again at that sub-step.
  std::vector<ForceTerm*> reaching;
  for (ForceTerm* t : terms)
    if (t->worst_case_within_reach() && t->worst_case_node_stiffness() > 0.0) reaching.push_back(t);
  std::vector<char> far;
  if (!reaching.empty()) {
    const StepContext first{context.time, context.h, context.step};
    for (ForceTerm* t : reaching)
      t->prepare(state, first);
    far = islands_out_of_reach(state, reaching);
    for (std::size_t g = 0; g < islands_.size(); ++g)
      if (far[g] == 0) islands_[g].wake();  // within reach
  }
  const Plan step_plan = plan(needed_substeps(context.h, far));
  stats.substeps = step_plan.fine;
  if (step_plan.strides.empty()) {
    wake();  // the uniform step moves every node
    step_uniform(state, terms, context, step_plan.fine, reaching);
  } else {
    step_multirate(state, terms, context, step_plan.fine, step_plan.strides, reaching);
  }
  return stats;
}

void ExplicitVerlet::wake() {
  for (Island& island : islands_)
    island.wake();
}

void ExplicitVerlet::wake_body(int body) {
  if (body < 0 || body >= static_cast<int>(island_of_body_.size())) return wake();
  const int island = island_of_body_[static_cast<std::size_t>(body)];
  if (island >= 0) islands_[static_cast<std::size_t>(island)].wake();
}

int ExplicitVerlet::islands_asleep() const {
  return static_cast<int>(
      std::count_if(islands_.begin(), islands_.end(), [](const Island& i) { return i.asleep; }));
}

void ExplicitVerlet::update_sleep(SimulationState& state, std::span<ForceTerm* const> terms,
                                  double h, int fine, const std::vector<char>& touched) {
  const double fine_h = h / fine;  // the forces a sleeping island received acted this long
  std::vector<char> driven(islands_.size(), 0);
  for (const ForceTerm* t : terms) {
    const int b = t->body();
    if (b >= 0 && b < static_cast<int>(island_of_body_.size()) && t->drives())
      driven[static_cast<std::size_t>(island_of_body_[static_cast<std::size_t>(b)])] = 1;
  }
  for (std::size_t g = 0; g < islands_.size(); ++g) {
    Island& island = islands_[g];
    if (island.asleep) {
      // Woken by an impulse: it takes what it received while asleep, whole.
      bool pushed = false;
      for (const int node : island.nodes)
        pushed = pushed || shared_impulse_[static_cast<std::size_t>(node)] != Vec3::Zero();
      if (!pushed) continue;
      island.wake();
      for (const int node : island.nodes) {
        const auto i = static_cast<std::size_t>(node);
        state.velocities[i] += (fine_h * state.inverse_masses[i]) * shared_impulse_[i];
        shared_impulse_[i].setZero();
      }
      continue;
    }
    if (!(sleep_threshold_ > 0.0)) continue;
    double fastest = 0.0;
    for (const int node : island.nodes)
      fastest = std::max(fastest, state.velocities[static_cast<std::size_t>(node)].squaredNorm());
    const bool calm = std::sqrt(fastest) * h < sleep_threshold_ && !touched[g] && !driven[g];
    island.calm_steps = calm ? island.calm_steps + 1 : 0;
    if (island.calm_steps < kCalmStepsToSleep) continue;
    for (const int node : island.nodes)
      state.velocities[static_cast<std::size_t>(node)].setZero();
    island.asleep = true;
  }
}

namespace {

bool among(std::span<ForceTerm* const> prepared, const ForceTerm* t) {
  return std::find(prepared.begin(), prepared.end(), t) != prepared.end();
}

}  // namespace

void ExplicitVerlet::step_uniform(SimulationState& state, std::span<ForceTerm* const> terms,
                                  const StepContext& context, int substeps,
                                  std::span<ForceTerm* const> prepared) {
  const double h = context.h / substeps;
  const std::size_t n = state.node_count();
  for (int s = 0; s < substeps; ++s) {
    const StepContext sub{context.time + s * h, h, context.step};
    for (ForceTerm* t : terms)
      if (s > 0 || !among(prepared, t)) t->prepare(state, sub);
    std::fill(forces_.begin(), forces_.end(), Vec3::Zero());
    for (ForceTerm* t : terms)
      t->add_forces(state.positions, state.velocities, forces_);
    // Symplectic Euler = position Verlet with the backward-difference velocity.
    for (std::size_t i = 0; i < n; ++i) {
      const double w = state.inverse_masses[i];
      if (w == 0.0) {
        state.velocities[i].setZero();
        continue;
      }
      state.velocities[i] += (h * w) * forces_[i];
      state.positions[i] += h * state.velocities[i];
    }
    state.time += h;
    const bool last = s + 1 == substeps;
    for (ForceTerm* t : terms)
      if (last || t->after_each_substep()) t->after_step(state);
  }
}

void ExplicitVerlet::step_multirate(SimulationState& state, std::span<ForceTerm* const> terms,
                                    const StepContext& context, int fine,
                                    const std::vector<int>& strides,
                                    std::span<ForceTerm* const> prepared) {
  // Terms acting per node (gravity) are prepared with the shared ones at every fine sub-step
  // but add their forces only at each island's own sub-steps, on its nodes.
  std::vector<ForceTerm*> shared, coupling, per_node;
  std::vector<std::vector<ForceTerm*>> own(islands_.size());
  for (ForceTerm* t : terms) {
    const int b = t->body();
    if (b >= 0 && b < static_cast<int>(island_of_body_.size())) {
      own[static_cast<std::size_t>(island_of_body_[static_cast<std::size_t>(b)])].push_back(t);
      continue;
    }
    shared.push_back(t);
    (t->acts_per_node() ? per_node : coupling).push_back(t);
  }
  const double h = context.h / fine;
  // The shared terms' forces add up in shared_impulse_ over the fine sub-steps until the
  // island of each node takes their mean and clears them.
  // A sleeping island's nodes keep what they received in earlier steps (update_sleep).
  for (std::size_t g = 0; g < islands_.size(); ++g)
    if (!islands_[g].asleep)
      for (const int node : islands_[g].nodes)
        shared_impulse_[static_cast<std::size_t>(node)].setZero();
  std::vector<char> touched(islands_.size(), 0);  // a term of any body pushed its nodes
  for (int s = 0; s < fine; ++s) {
    const bool last = s + 1 == fine;
    const StepContext sub{context.time + s * h, h, context.step};
    for (ForceTerm* t : shared)
      if (s > 0 || !among(prepared, t)) t->prepare(state, sub);
    for (ForceTerm* t : coupling)
      t->add_forces(state.positions, state.velocities, shared_impulse_);
    for (std::size_t g = 0; g < islands_.size(); ++g) {
      const std::vector<int>& nodes = islands_[g].nodes;
      const int stride = strides[g];
      if (islands_[g].asleep || (s + 1) % stride != 0) continue;
      // The island's own sub-step, from the fine sub-step it began at.
      const double big = stride * h;
      const StepContext own_sub{context.time + (s + 1 - stride) * h, big, context.step};
      for (ForceTerm* t : own[g])
        if (s + 1 > stride || !among(prepared, t)) t->prepare(state, own_sub);
      for (const int i : nodes)
        forces_[static_cast<std::size_t>(i)].setZero();
      for (ForceTerm* t : own[g])
        t->add_forces(state.positions, state.velocities, forces_);
      for (ForceTerm* t : per_node)
        t->add_node_forces(nodes, state.positions, state.velocities, forces_);
      const double mean = 1.0 / stride;
      for (const int node : nodes) {
        const auto i = static_cast<std::size_t>(node);
        const double w = state.inverse_masses[i];
        if (shared_impulse_[i] != Vec3::Zero()) touched[g] = 1;
        const Vec3 force = forces_[i] + mean * shared_impulse_[i];
        shared_impulse_[i].setZero();
        if (w == 0.0) {
          state.velocities[i].setZero();
          continue;
        }
        state.velocities[i] += (big * w) * force;
        state.positions[i] += big * state.velocities[i];
      }
      for (ForceTerm* t : own[g])
        if (last || t->after_each_substep()) t->after_step(state);
    }
    state.time += h;
    for (ForceTerm* t : shared)
      if (last || t->after_each_substep()) t->after_step(state);
  }
  update_sleep(state, terms, context.h, fine, touched);
}

}  // namespace viscera::sim
