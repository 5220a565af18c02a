#include "simulator/dynamics/explicit_verlet.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

#include "simulator/physics/stable_step.h"

namespace viscera::sim {

double largest_eigenvalue(const BlockSparseMatrix& a, std::span<const double> inverse_mass,
                          int max_iterations, double tolerance) {
  const std::vector<int> one_group(a.node_count(), 0);
  return largest_eigenvalues(a, inverse_mass, one_group, 1, max_iterations, tolerance)[0];
}

std::vector<double> largest_eigenvalues(const BlockSparseMatrix& a,
                                        std::span<const double> inverse_mass,
                                        std::span<const int> group_of_node, int groups,
                                        int max_iterations, double tolerance) {
  const std::size_t n = a.node_count();
  const auto g_count = static_cast<std::size_t>(groups);
  std::vector<double> scale(n);
  for (std::size_t i = 0; i < n; ++i)
    scale[i] = std::sqrt(inverse_mass[i]);
  // A fixed pseudo-random start (a linear congruential sequence): deterministic everywhere.
  std::vector<Vec3> x(n), y(n), scaled(n);
  std::uint64_t seed = 0x9E3779B97F4A7C15ull;
  for (auto& p : x)
    for (int k = 0; k < 3; ++k) {
      seed = seed * 6364136223846793005ull + 1442695040888963407ull;
      p[k] = static_cast<double>(seed >> 11) * 0x1.0p-53 - 0.5;
    }
  std::vector<double> lambda(g_count, 0.0), checkpoint(g_count, 0.0), norm(g_count),
      quotient(g_count);
  std::vector<char> running(g_count, 1), row_on(n, 0);
  int still_running = groups;
  const auto group = [&](std::size_t i) { return static_cast<std::size_t>(group_of_node[i]); };
  for (int it = 0; it < max_iterations && still_running > 0; ++it) {
    std::fill(norm.begin(), norm.end(), 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      x[i] *= scale[i] > 0.0 ? 1.0 : 0.0;
      if (group_of_node[i] >= 0) norm[group(i)] += x[i].squaredNorm();
    }
    for (std::size_t g = 0; g < g_count; ++g) {
      norm[g] = std::sqrt(norm[g]);
      if (running[g] != 0 && !(norm[g] > 0.0)) {
        lambda[g] = 0.0;  // every node held: no motion to bound
        running[g] = 0;
        --still_running;
      }
    }
    if (still_running == 0) break;
    for (std::size_t i = 0; i < n; ++i) {
      const bool on = group_of_node[i] >= 0 && running[group(i)] != 0;
      row_on[i] = on ? 1 : 0;
      scaled[i] = on ? Vec3(x[i] * (scale[i] / norm[group(i)])) : Vec3::Zero();
    }
    // No block joins two groups: the rows of the groups that converged (or that are not
    // asked for) would be zero, so only the running groups' rows are multiplied.
    a.multiply_rows(scaled, y, row_on);
    std::fill(quotient.begin(), quotient.end(), 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      y[i] *= scale[i];
      if (group_of_node[i] >= 0 && running[group(i)] != 0)
        quotient[group(i)] += y[i].dot(x[i]) / norm[group(i)];
    }
    for (std::size_t g = 0; g < g_count; ++g)
      if (running[g] != 0) lambda[g] = std::max(lambda[g], quotient[g]);
    x.swap(y);
    if (it % 20 == 19) {
      for (std::size_t g = 0; g < g_count; ++g) {
        if (running[g] == 0) continue;
        if (lambda[g] <= checkpoint[g] * (1.0 + tolerance)) {
          running[g] = 0;
          --still_running;
        }
        checkpoint[g] = lambda[g];
      }
    }
  }
  return lambda;
}

namespace {

/// Rest Hessians (positive semi-definite parts) and damping matrices of `terms` at the current
/// state, plus k·I on every node a contact-like term may press on later.
void assemble(const SimulationState& state, std::span<ForceTerm* const> terms,
              const BlockPattern& pattern, BlockSparseMatrix& stiffness,
              BlockSparseMatrix& damping) {
  stiffness.set_pattern(pattern);
  damping.set_structure_of(stiffness);
  for (ForceTerm* t : terms) {
    t->add_stiffness(state.positions, 1.0, true, stiffness);
    t->add_damping(state.positions, 1.0, damping);
    const double k = t->worst_case_node_stiffness();
    if (k > 0.0 && !t->worst_case_within_reach())
      for (const int node : t->worst_case_nodes())
        stiffness.block(stiffness.diagonal_slot(node)) += k * Mat3::Identity();
  }
}

}  // namespace

void ExplicitVerlet::plan_islands(const SimulationState& state, std::span<ForceTerm* const> terms,
                                  BlockSparseMatrix& stiffness, const BlockSparseMatrix& damping,
                                  std::span<const int> group_of_node,
                                  std::span<const int> island_of_group) {
  const int groups = static_cast<int>(island_of_group.size());
  const auto damping_rate =
      largest_eigenvalues(damping, state.inverse_masses, group_of_node, groups);
  // Out of the reach of a term whose worst case acts only within reach (the proxy far from an
  // island), then with it everywhere (the plan for islands within reach, and the bound).
  const auto far_omega_squared =
      largest_eigenvalues(stiffness, state.inverse_masses, group_of_node, groups);
  bool reaching = false;
  for (ForceTerm* t : terms) {
    const double k = t->worst_case_node_stiffness();
    if (k <= 0.0 || !t->worst_case_within_reach()) continue;
    reaching = true;
    for (const int node : t->worst_case_nodes())
      stiffness.block(stiffness.diagonal_slot(node)) += k * Mat3::Identity();
  }
  const auto omega_squared =
      reaching ? largest_eigenvalues(stiffness, state.inverse_masses, group_of_node, groups)
               : far_omega_squared;
  for (std::size_t g = 0; g < island_of_group.size(); ++g) {
    Island& island = islands_[static_cast<std::size_t>(island_of_group[g])];
    island.stable_step = kStableStepSafety * verlet_stable_step(omega_squared[g], damping_rate[g]);
    island.far_stable_step =
        kStableStepSafety * verlet_stable_step(far_omega_squared[g], damping_rate[g]);
  }
  stable_step_ = std::numeric_limits<double>::infinity();
  for (const Island& island : islands_)
    stable_step_ = std::min(stable_step_, island.stable_step);
  if (islands_.empty()) stable_step_ = kStableStepSafety * verlet_stable_step(0.0, 0.0);
}

void ExplicitVerlet::stiffness_changed(const SimulationState& state,
                                       std::span<ForceTerm* const> terms, int body) {
  const bool planned = ready_ && shared_impulse_.size() == state.node_count() && body >= 0 &&
                       body < static_cast<int>(island_of_body_.size()) &&
                       island_of_body_[static_cast<std::size_t>(body)] >= 0;
  if (!planned) return topology_changed(state, terms);
  BlockPattern pattern(state.node_count());
  for (ForceTerm* t : terms)
    t->declare_blocks(pattern);
  BlockSparseMatrix stiffness, damping;
  assemble(state, terms, pattern, stiffness, damping);
  const int island = island_of_body_[static_cast<std::size_t>(body)];
  std::vector<int> group_of_node(state.node_count(), -1);
  for (const int node : islands_[static_cast<std::size_t>(island)].nodes)
    group_of_node[static_cast<std::size_t>(node)] = 0;
  const std::array<int, 1> only{island};
  plan_islands(state, terms, stiffness, damping, group_of_node, only);
}

void ExplicitVerlet::topology_changed(const SimulationState& state,
                                      std::span<ForceTerm* const> terms) {
  BlockPattern pattern(state.node_count());
  for (ForceTerm* t : terms)
    t->declare_blocks(pattern);
  BlockSparseMatrix stiffness, damping;
  assemble(state, terms, pattern, stiffness, damping);

  // Islands: bodies joined by a declared block, numbered in the order of their lowest body.
  const auto& bodies = state.bodies();
  std::vector<int> body_of_node(state.node_count(), -1), root(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    root[b] = static_cast<int>(b);
    for (int k = 0; k < bodies[b].count; ++k)
      body_of_node[static_cast<std::size_t>(bodies[b].first + k)] = static_cast<int>(b);
  }
  const auto find = [&](int b) {
    while (root[static_cast<std::size_t>(b)] != b)
      b = root[static_cast<std::size_t>(b)] =
          root[static_cast<std::size_t>(root[static_cast<std::size_t>(b)])];
    return b;
  };
  for (const auto& [i, j] : pattern.pairs()) {
    const int a = body_of_node[static_cast<std::size_t>(i)];
    const int b = body_of_node[static_cast<std::size_t>(j)];
    if (a < 0 || b < 0) continue;
    const int ra = find(a), rb = find(b);
    if (ra != rb) root[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
  }
  // A re-plan with the same nodes (a stiffness changed, a term was added) keeps the sleep of
  // the islands whose nodes it leaves as they were, and what they received asleep: a grasp on
  // the tube must not wake a quiet vein. Any other island starts awake.
  const std::vector<Island> before = std::move(islands_);
  const bool same_nodes = shared_impulse_.size() == state.node_count();
  islands_.clear();
  island_of_body_.assign(bodies.size(), -1);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const int r = find(static_cast<int>(b));
    if (island_of_body_[static_cast<std::size_t>(r)] < 0) {
      island_of_body_[static_cast<std::size_t>(r)] = static_cast<int>(islands_.size());
      islands_.emplace_back();
    }
    const int island = island_of_body_[static_cast<std::size_t>(r)];
    island_of_body_[b] = island;
    for (int k = 0; k < bodies[b].count; ++k)
      islands_[static_cast<std::size_t>(island)].nodes.push_back(bodies[b].first + k);
  }
  every_node_in_an_island_ =
      std::none_of(body_of_node.begin(), body_of_node.end(), [](int b) { return b < 0; });
  std::vector<int> group_of_node(state.node_count(), -1);
  for (std::size_t i = 0; i < group_of_node.size(); ++i)
    if (body_of_node[i] >= 0)
      group_of_node[i] = island_of_body_[static_cast<std::size_t>(body_of_node[i])];
  std::vector<int> every_island(islands_.size());
  for (std::size_t g = 0; g < every_island.size(); ++g)
    every_island[g] = static_cast<int>(g);
  plan_islands(state, terms, stiffness, damping, group_of_node, every_island);
  forces_.assign(state.node_count(), Vec3::Zero());
  if (same_nodes) {
    std::map<int, const Island*> by_first_node;
    for (const Island& island : before)
      if (!island.nodes.empty()) by_first_node[island.nodes.front()] = &island;
    for (Island& island : islands_) {
      if (island.nodes.empty()) continue;
      const auto it = by_first_node.find(island.nodes.front());
      if (it == by_first_node.end() || it->second->nodes != island.nodes) continue;
      island.asleep = it->second->asleep;
      island.calm_steps = it->second->calm_steps;
    }
    for (const Island& island : islands_)
      if (!island.asleep)
        for (const int node : island.nodes)
          shared_impulse_[static_cast<std::size_t>(node)].setZero();
  } else {
    shared_impulse_.assign(state.node_count(), Vec3::Zero());
  }
  ready_ = true;
}

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
