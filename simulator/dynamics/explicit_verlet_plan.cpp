#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

#include "simulator/dynamics/explicit_verlet.h"
#include "simulator/physics/stable_step.h"

// The plan of an explicit step: the islands, their stable sub-steps from the largest
// eigenvalues, and the re-plans after a change of stiffness or topology.

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
  replan(state, terms, -1);
}

void ExplicitVerlet::body_topology_changed(const SimulationState& state,
                                           std::span<ForceTerm* const> terms, int body) {
  replan(state, terms, body);
}

void ExplicitVerlet::replan(const SimulationState& state, std::span<ForceTerm* const> terms,
                            int changed_body) {
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
  const std::vector<int> island_of_body_before = std::move(island_of_body_);
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
  // After one body's mesh changed (a crack, a cut), the islands without it whose bodies kept
  // their node counts keep their plans, sleep and impulses, their nodes shifted with the
  // bodies before them: a tube tearing knot by knot does not re-plan the whole scene each step.
  std::vector<int> kept(islands_.size(), -1);  // per island: the island it was, if kept
  if (changed_body >= 0 && ready_ && planned_layout_.size() == bodies.size())
    kept = islands_kept(bodies, island_of_body_before, before, changed_body);
  std::vector<int> group_of_node(state.node_count(), -1), planned;
  for (std::size_t g = 0; g < islands_.size(); ++g) {
    if (kept[g] >= 0) {
      const Island& old = before[static_cast<std::size_t>(kept[g])];
      Island& island = islands_[g];
      island.stable_step = old.stable_step;
      island.far_stable_step = old.far_stable_step;
      continue;
    }
    for (const int node : islands_[g].nodes)
      group_of_node[static_cast<std::size_t>(node)] = static_cast<int>(planned.size());
    planned.push_back(static_cast<int>(g));
  }
  plan_islands(state, terms, stiffness, damping, group_of_node, planned);
  forces_.assign(state.node_count(), Vec3::Zero());
  if (planned.size() < islands_.size()) {
    std::vector<Vec3> impulse(state.node_count(), Vec3::Zero());
    for (std::size_t g = 0; g < islands_.size(); ++g) {
      if (kept[g] < 0) continue;
      const Island& old = before[static_cast<std::size_t>(kept[g])];
      islands_[g].asleep = old.asleep;
      islands_[g].calm_steps = old.calm_steps;
      for (std::size_t k = 0; k < old.nodes.size(); ++k)
        impulse[static_cast<std::size_t>(islands_[g].nodes[k])] =
            shared_impulse_[static_cast<std::size_t>(old.nodes[k])];
    }
    shared_impulse_ = std::move(impulse);
  } else if (same_nodes) {
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
  planned_layout_.clear();
  for (const auto& body : bodies)
    planned_layout_.push_back(body.count);
  ready_ = true;
}

std::vector<int> ExplicitVerlet::islands_kept(std::span<const BodyNodes> bodies,
                                              std::span<const int> island_of_body_before,
                                              std::span<const Island> before,
                                              int changed_body) const {
  std::vector<std::vector<int>> bodies_now(islands_.size()), bodies_then(before.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    bodies_now[static_cast<std::size_t>(island_of_body_[b])].push_back(static_cast<int>(b));
    if (island_of_body_before[b] >= 0)
      bodies_then[static_cast<std::size_t>(island_of_body_before[b])].push_back(
          static_cast<int>(b));
  }
  std::vector<int> kept(islands_.size(), -1);
  for (std::size_t g = 0; g < islands_.size(); ++g) {
    const std::vector<int>& members = bodies_now[g];
    if (members.empty()) continue;
    const int old = island_of_body_before[static_cast<std::size_t>(members.front())];
    if (old < 0 || bodies_then[static_cast<std::size_t>(old)] != members) continue;
    const bool unchanged = std::all_of(members.begin(), members.end(), [&](int b) {
      return b != changed_body && planned_layout_[static_cast<std::size_t>(b)] ==
                                      bodies[static_cast<std::size_t>(b)].count;
    });
    if (unchanged && before[static_cast<std::size_t>(old)].nodes.size() == islands_[g].nodes.size())
      kept[g] = old;
  }
  return kept;
}

}  // namespace viscera::sim
