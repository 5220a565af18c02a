// The explicit integrator's multi-rate sub-steps (explicit_verlet.h): bodies that no term joins
// are islands stepped at their own rates; terms that may touch any body are evaluated at every
// fine sub-step and a slow island takes their mean.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "simulator/dynamics/block_sparse_matrix.h"
#include "simulator/dynamics/explicit_verlet.h"
#include "simulator/dynamics/force_term.h"
#include "simulator/dynamics/gravity_term.h"
#include "simulator/dynamics/simulation_state.h"

namespace viscera::sim {
namespace {

/// Zero-rest-length springs between nodes of one body, E = ½ k |x_j − x_i − r_ij|² with r_ij
/// the rest offset: a constant Hessian, so the stable step is exact.
class OffsetSprings : public ForceTerm {
 public:
  OffsetSprings(int body, std::vector<std::array<int, 2>> pairs, double stiffness,
                const SimulationState& state)
      : body_(body), pairs_(std::move(pairs)), k_(stiffness) {
    for (const auto& [i, j] : pairs_)
      rest_.push_back(state.positions[static_cast<std::size_t>(j)] -
                      state.positions[static_cast<std::size_t>(i)]);
  }
  std::string name() const override { return "offset springs"; }
  void set_stiffness(double k) { k_ = k; }  ///< N/m: the coefficients changed in place
  int body() const override { return body_; }
  double energy(std::span<const Vec3> x) const override {
    double e = 0.0;
    for (std::size_t s = 0; s < pairs_.size(); ++s)
      e += 0.5 * k_ * (x[pairs_[s][1]] - x[pairs_[s][0]] - rest_[s]).squaredNorm();
    return e;
  }
  double add_forces(std::span<const Vec3> x, std::span<const Vec3>,
                    std::span<Vec3> f) const override {
    for (std::size_t s = 0; s < pairs_.size(); ++s) {
      const Vec3 stretch = x[pairs_[s][1]] - x[pairs_[s][0]] - rest_[s];
      f[pairs_[s][0]] += k_ * stretch;
      f[pairs_[s][1]] -= k_ * stretch;
    }
    return energy(x);
  }
  void declare_blocks(BlockPattern& pattern) const override {
    for (const auto& [i, j] : pairs_)
      pattern.add(i, j);
  }
  void add_stiffness(std::span<const Vec3>, double scale, bool,
                     BlockSparseMatrix& m) const override {
    for (const auto& [i, j] : pairs_) {
      m.add_symmetric(i, i, scale * k_ * Mat3::Identity());
      m.add_symmetric(j, j, scale * k_ * Mat3::Identity());
      m.add_symmetric(i, j, -scale * k_ * Mat3::Identity());
    }
  }

 private:
  int body_;
  std::vector<std::array<int, 2>> pairs_;
  std::vector<Vec3> rest_;
  double k_;
};

/// A spring between a node of one body and a node of another that declares no block (as a
/// contact that appears after the topology change): a term of any body, planned for by its
/// worst-case stiffness.
class CrossSpring : public ForceTerm {
 public:
  CrossSpring(int a, int b, double stiffness, const SimulationState& state)
      : nodes_{a, b}, k_(stiffness), rest_(state.positions[b] - state.positions[a]) {}
  std::string name() const override { return "cross spring"; }
  double energy(std::span<const Vec3> x) const override {
    return 0.5 * k_ * (x[nodes_[1]] - x[nodes_[0]] - rest_).squaredNorm();
  }
  double add_forces(std::span<const Vec3> x, std::span<const Vec3>,
                    std::span<Vec3> f) const override {
    const Vec3 stretch = x[nodes_[1]] - x[nodes_[0]] - rest_;
    f[nodes_[0]] += k_ * stretch;
    f[nodes_[1]] -= k_ * stretch;
    return energy(x);
  }
  void declare_blocks(BlockPattern&) const override {}
  void add_stiffness(std::span<const Vec3>, double, bool, BlockSparseMatrix&) const override {}
  double worst_case_node_stiffness() const override { return k_; }
  std::span<const int> worst_case_nodes() const override { return nodes_; }

 private:
  std::array<int, 2> nodes_;
  double k_;
  Vec3 rest_;
};

/// A stiff spring pulling `node` towards where it started, planned for on `planned` nodes but
/// acting only within a box the test moves (as the proxy acts only near the tip).
class ReachingSpring : public ForceTerm {
 public:
  ReachingSpring(int node, std::vector<int> planned, double stiffness, const SimulationState& state)
      : node_(node), planned_(std::move(planned)), k_(stiffness), anchor_(state.positions[node]) {}
  std::string name() const override { return "reaching spring"; }
  void prepare(const SimulationState&, const StepContext&) override { ++prepared; }
  double energy(std::span<const Vec3> x) const override {
    return 0.5 * k_ * (x[node_] - anchor_).squaredNorm();
  }
  double add_forces(std::span<const Vec3> x, std::span<const Vec3>,
                    std::span<Vec3> f) const override {
    f[node_] -= k_ * (x[node_] - anchor_);
    return energy(x);
  }
  void declare_blocks(BlockPattern&) const override {}
  void add_stiffness(std::span<const Vec3>, double, bool, BlockSparseMatrix&) const override {}
  double worst_case_node_stiffness() const override { return k_; }
  std::span<const int> worst_case_nodes() const override { return planned_; }
  bool worst_case_within_reach() const override { return true; }
  core::BoundingBox reach() const override { return reach_; }

  core::BoundingBox reach_;
  int prepared = 0;

 private:
  int node_;
  std::vector<int> planned_;
  double k_;
  Vec3 anchor_;
};

/// A constant force on one node while `on` (a term of any body, as a tool that starts
/// pushing).
class Push : public ForceTerm {
 public:
  Push(int node, const Vec3& force) : node_(node), force_(force) {}
  std::string name() const override { return "push"; }
  double energy(std::span<const Vec3>) const override { return 0.0; }
  double add_forces(std::span<const Vec3>, std::span<const Vec3>,
                    std::span<Vec3> f) const override {
    if (on) f[static_cast<std::size_t>(node_)] += force_;
    return 0.0;
  }
  void declare_blocks(BlockPattern&) const override {}
  void add_stiffness(std::span<const Vec3>, double, bool, BlockSparseMatrix&) const override {}
  bool on = false;

 private:
  int node_;
  Vec3 force_;
};

/// A pair of free nodes 1 cm apart: `mass` kg each on a spring of `stiffness` N/m.
void add_pair(SimulationState& state, double mass, double stiffness, const Vec3& at,
              std::vector<std::unique_ptr<ForceTerm>>& terms) {
  const std::vector<Vec3> rest = {at, at + Vec3(0.01, 0.0, 0.0)};
  const std::vector<double> masses = {mass, mass};
  const std::vector<std::uint8_t> fixed = {0, 0};
  const int body = state.add_body("pair", rest, masses, fixed);
  const int first = state.body(body).first;
  terms.push_back(std::make_unique<OffsetSprings>(
      body, std::vector<std::array<int, 2>>{{first, first + 1}}, stiffness, state));
}

std::vector<ForceTerm*> pointers(const std::vector<std::unique_ptr<ForceTerm>>& terms) {
  std::vector<ForceTerm*> out;
  for (const auto& t : terms)
    out.push_back(t.get());
  return out;
}

// A 1 g pair on 15 kN/m needs 4 sub-steps of a 1 ms step (ω² = 2k/m = 3·10⁷ /s², 0.8 · 2/ω =
// 0.29 ms); a 1 kg pair on 100 N/m needs 1.
constexpr double kLightMass = 1e-3, kStiff = 1.5e4, kHeavyMass = 1.0, kSoft = 100.0;

void kick(SimulationState& state) {
  for (std::size_t i = 0; i < state.node_count(); ++i)
    state.velocities[i] = Vec3(0.01 * static_cast<double>(i + 1), -0.02, 0.005 * (i % 2 ? 1 : -1));
}

/// Steps a heavy and a light pair together and each alone, with gravity when `falling` (a term
/// acting per node: applied at each island's own sub-steps), and expects the same bits.
void expect_islands_to_move_as_alone(bool falling) {
  SimulationState both, heavy_alone, light_alone;
  std::vector<std::unique_ptr<ForceTerm>> both_terms, heavy_terms, light_terms;
  add_pair(both, kHeavyMass, kSoft, Vec3::Zero(), both_terms);
  add_pair(both, kLightMass, kStiff, Vec3(0.0, 0.05, 0.0), both_terms);
  add_pair(heavy_alone, kHeavyMass, kSoft, Vec3::Zero(), heavy_terms);
  add_pair(light_alone, kLightMass, kStiff, Vec3(0.0, 0.05, 0.0), light_terms);
  if (falling) {
    const Vec3 g(0.0, 0.0, -9.81);
    both_terms.push_back(std::make_unique<GravityTerm>(g, both));
    heavy_terms.push_back(std::make_unique<GravityTerm>(g, heavy_alone));
    light_terms.push_back(std::make_unique<GravityTerm>(g, light_alone));
  }
  kick(both);
  kick(heavy_alone);
  light_alone.velocities = {both.velocities[2], both.velocities[3]};

  ExplicitVerlet multirate, heavy_integrator, light_integrator;
  const auto t_both = pointers(both_terms), t_heavy = pointers(heavy_terms),
             t_light = pointers(light_terms);
  multirate.topology_changed(both, t_both);
  heavy_integrator.topology_changed(heavy_alone, t_heavy);
  light_integrator.topology_changed(light_alone, t_light);
  ASSERT_EQ(multirate.island_stable_steps().size(), 2u);
  ASSERT_EQ(heavy_integrator.substeps(1e-3), 1);
  ASSERT_EQ(light_integrator.substeps(1e-3), 4);
  ASSERT_EQ(multirate.substeps(1e-3), 4);
  for (int k = 0; k < 500; ++k) {
    const StepContext step{1e-3 * k, 1e-3, k + 1};
    EXPECT_EQ(multirate.step(both, t_both, step).substeps, 4);
    heavy_integrator.step(heavy_alone, t_heavy, step);
    light_integrator.step(light_alone, t_light, step);
  }
  // The heavy pair took one sub-step a step, the light pair four: the same bits as alone.
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(both.positions[static_cast<std::size_t>(i)], heavy_alone.positions[i]);
    EXPECT_EQ(both.velocities[static_cast<std::size_t>(i)], heavy_alone.velocities[i]);
    EXPECT_EQ(both.positions[static_cast<std::size_t>(i) + 2], light_alone.positions[i]);
  }
  // Not a trivial agreement: stepped four times per step, the heavy pair would differ.
  EXPECT_GT((both.positions[0] - both.rest_positions[0]).norm(), 1e-4);
  // Falling for 0.5 s: ½ g t² = 1.2 m, the light pair as far as the heavy one.
  if (falling) {
    EXPECT_LT(both.positions[2].z(), -1.0);
  }
}

TEST(MultirateVerlet, each_island_moves_as_it_would_alone_at_its_own_rate) {
  expect_islands_to_move_as_alone(false);
}

TEST(MultirateVerlet, gravity_acts_at_each_island_own_rate_as_it_would_alone) {
  expect_islands_to_move_as_alone(true);
}

TEST(MultirateVerlet, a_term_joining_islands_gives_both_the_same_impulse_so_momentum_is_kept) {
  SimulationState state;
  std::vector<std::unique_ptr<ForceTerm>> terms;
  add_pair(state, kHeavyMass, kSoft, Vec3::Zero(), terms);
  add_pair(state, kLightMass, kStiff, Vec3(0.0, 0.02, 0.0), terms);
  terms.push_back(std::make_unique<CrossSpring>(1, 2, 50.0, state));
  kick(state);
  const auto momentum = [&] {
    Vec3 p = Vec3::Zero();
    for (std::size_t i = 0; i < state.node_count(); ++i)
      p += state.masses[i] * state.velocities[i];
    return p;
  };
  const auto energy = [&] {
    double e = 0.0;
    for (std::size_t i = 0; i < state.node_count(); ++i)
      e += 0.5 * state.masses[i] * state.velocities[i].squaredNorm();
    for (const auto& t : terms)
      e += t->energy(state.positions);
    return e;
  };
  ExplicitVerlet integrator;
  const auto t = pointers(terms);
  integrator.topology_changed(state, t);
  ASSERT_EQ(integrator.substeps(1e-3), 4);  // multi-rate: the islands need 1 and 4
  const Vec3 p0 = momentum();
  const double e0 = energy();
  double cross_work = 0.0;  // the cross spring does change each pair's momentum
  for (int k = 0; k < 2000; ++k) {
    const Vec3 before = state.masses[1] * state.velocities[1];
    integrator.step(state, t, StepContext{1e-3 * k, 1e-3, k + 1});
    cross_work += (state.masses[1] * state.velocities[1] - before).norm();
    ASSERT_LT((momentum() - p0).norm(), 1e-12 * (p0.norm() + 1e-3)) << "step " << k;
  }
  EXPECT_GT(cross_work, 1e-4);
  // Symplectic and undamped: the energy stays within a few per cent of where it began.
  EXPECT_NEAR(energy(), e0, 0.05 * e0);
}

TEST(MultirateVerlet, a_term_acting_within_reach_is_planned_only_for_the_islands_in_reach) {
  // Two pairs of 1 g knots 10 cm apart on 0.1 N/m springs, each needing one sub-step of a 1 ms
  // step; 30 kN/m planned on a knot needs 4 (ω² ≈ 3·10⁷ /s², 0.8 · 2/ω = 0.29 ms).
  SimulationState state;
  std::vector<std::unique_ptr<ForceTerm>> terms;
  add_pair(state, kLightMass, kSoft * 1e-3, Vec3::Zero(), terms);
  add_pair(state, kLightMass, kSoft * 1e-3, Vec3(0.1, 0.0, 0.0), terms);
  auto reaching = std::make_unique<ReachingSpring>(3, std::vector<int>{0, 1, 2, 3}, 3.0e4, state);
  ReachingSpring* spring = reaching.get();
  terms.push_back(std::move(reaching));
  ExplicitVerlet integrator;
  const auto t = pointers(terms);
  integrator.topology_changed(state, t);
  ASSERT_EQ(integrator.substeps(1e-3), 4);  // the bound: planned on every node
  const auto box_around = [](const Vec3& c) {
    core::BoundingBox b;
    b.add(c - Vec3::Constant(0.02));
    b.add(c + Vec3::Constant(0.02));
    return b;
  };
  long long step = 0;
  const auto take = [&] {
    ++step;
    return integrator.step(state, t, StepContext{1e-3 * (step - 1), 1e-3, step}).substeps;
  };
  spring->reach_ = box_around(Vec3(0.0, 0.0, 1.0));  // far from both
  EXPECT_EQ(take(), 1);
  spring->reach_ = box_around(state.positions[2]);  // the second pair only: multi-rate
  spring->prepared = 0;
  EXPECT_EQ(take(), 4);
  EXPECT_EQ(spring->prepared, 4);  // once per fine sub-step, the first before the plan
  spring->reach_ = box_around(Vec3(0.05, 0.0, 0.0));  // wide enough for both: uniform
  spring->reach_.add(Vec3(0.2, 0.0, 0.0));
  spring->reach_.add(Vec3(-0.1, 0.0, 0.0));
  EXPECT_EQ(take(), 4);
  for (const Vec3& x : state.positions)
    EXPECT_TRUE(x.allFinite());
}

}  // namespace
}  // namespace viscera::sim

namespace viscera::sim {
namespace {

TEST(MultirateVerlet, a_quiet_island_sleeps_and_a_push_wakes_it_with_its_whole_impulse) {
  // The heavy pair rests; the light pair rings (undamped) beside it. With sleeping on, the
  // heavy pair stops after kCalmStepsToSleep calm steps and stays exactly still while the light
  // pair moves as it would alone; a push on the heavy pair wakes it, and its momentum is the
  // push's impulse to rounding, the step it slept through included.
  SimulationState both, light_alone;
  std::vector<std::unique_ptr<ForceTerm>> terms, light_terms;
  add_pair(both, kHeavyMass, kSoft, Vec3::Zero(), terms);
  add_pair(both, kLightMass, kStiff, Vec3(0.0, 0.05, 0.0), terms);
  add_pair(light_alone, kLightMass, kStiff, Vec3(0.0, 0.05, 0.0), light_terms);
  auto push = std::make_unique<Push>(0, Vec3(0.0, 0.0, 0.5));
  Push* pusher = push.get();
  terms.push_back(std::move(push));
  both.velocities[2] = light_alone.velocities[0] = Vec3(0.0, 0.0, 0.01);
  ExplicitVerlet integrator, alone;
  integrator.set_sleep_threshold(1e-9);
  const auto t = pointers(terms), t_alone = pointers(light_terms);
  integrator.topology_changed(both, t);
  alone.topology_changed(light_alone, t_alone);
  const std::vector<Vec3> rest = both.positions;
  int step = 0;
  const auto advance = [&] {
    ++step;
    const StepContext context{1e-3 * step, 1e-3, step};
    integrator.step(both, t, context);
    alone.step(light_alone, t_alone, context);
  };
  while (step < ExplicitVerlet::kCalmStepsToSleep - 1)
    advance();
  EXPECT_EQ(integrator.islands_asleep(), 0);
  advance();
  ASSERT_EQ(integrator.islands_asleep(), 1);  // the heavy pair; the light one rings on
  for (int k = 0; k < 100; ++k)
    advance();
  EXPECT_EQ(both.positions[0], rest[0]);
  EXPECT_EQ(both.positions[1], rest[1]);
  EXPECT_EQ(both.positions[2], light_alone.positions[0]);
  EXPECT_EQ(both.velocities[3], light_alone.velocities[1]);
  pusher->on = true;
  const int pushed_from = step;
  advance();  // pushed while asleep: it wakes after this step with what it received
  EXPECT_EQ(integrator.islands_asleep(), 0);
  for (int k = 0; k < 50; ++k)
    advance();
  const Vec3 momentum = kHeavyMass * (both.velocities[0] + both.velocities[1]);
  const double impulse = 0.5 * 1e-3 * (step - pushed_from);
  EXPECT_NEAR(momentum.z(), impulse, 1e-12 * impulse);
  EXPECT_GT(both.positions[0].z(), rest[0].z());
}

}  // namespace
TEST(MultirateVerlet, a_replan_with_the_same_nodes_keeps_the_quiet_islands_asleep) {
  // A stiffness change or a new term re-plans the step (topology_changed with the same
  // nodes): the sleeping heavy pair sleeps on, and wake_body wakes only the island named.
  SimulationState both;
  std::vector<std::unique_ptr<ForceTerm>> terms;
  add_pair(both, kHeavyMass, kSoft, Vec3::Zero(), terms);
  add_pair(both, kLightMass, kStiff, Vec3(0.0, 0.05, 0.0), terms);
  both.velocities[2] = Vec3(0.0, 0.0, 0.01);
  ExplicitVerlet integrator;
  integrator.set_sleep_threshold(1e-9);
  const auto t = pointers(terms);
  integrator.topology_changed(both, t);
  for (int step = 1; step <= ExplicitVerlet::kCalmStepsToSleep; ++step)
    integrator.step(both, t, StepContext{1e-3 * step, 1e-3, step});
  ASSERT_EQ(integrator.islands_asleep(), 1);
  integrator.topology_changed(both, t);  // the same nodes: a re-plan
  EXPECT_EQ(integrator.islands_asleep(), 1);
  integrator.wake_body(1);  // the ringing light pair's body: the heavy one sleeps on
  EXPECT_EQ(integrator.islands_asleep(), 1);
  integrator.wake_body(0);
  EXPECT_EQ(integrator.islands_asleep(), 0);
  // A state with other nodes (a cut) starts every island awake.
  for (int step = 1; step <= ExplicitVerlet::kCalmStepsToSleep; ++step)
    integrator.step(both, t, StepContext{1e-3 * step, 1e-3, step});
  ASSERT_EQ(integrator.islands_asleep(), 1);
  SimulationState more = both;
  add_pair(more, kHeavyMass, kSoft, Vec3(0.0, -0.05, 0.0), terms);
  integrator.topology_changed(more, pointers(terms));
  EXPECT_EQ(integrator.islands_asleep(), 0);
}

TEST(MultirateVerlet, a_stiffness_change_replans_its_island_alone_as_a_whole_replan_would) {
  // The light pair stiffened 4× in place: stiffness_changed re-plans its island to the bits a
  // whole topology_changed gives (halving its stable sub-step) and leaves the sleeping heavy
  // pair's plan and sleep alone.
  SimulationState both;
  std::vector<std::unique_ptr<ForceTerm>> terms;
  add_pair(both, kHeavyMass, kSoft, Vec3::Zero(), terms);
  add_pair(both, kLightMass, kStiff, Vec3(0.0, 0.05, 0.0), terms);
  ExplicitVerlet integrator;
  integrator.set_sleep_threshold(1e-9);
  const auto t = pointers(terms);
  integrator.topology_changed(both, t);
  const std::vector<double> before = integrator.island_stable_steps();
  for (int step = 1; step <= ExplicitVerlet::kCalmStepsToSleep; ++step)
    integrator.step(both, t, StepContext{1e-3 * step, 1e-3, step});
  ASSERT_EQ(integrator.islands_asleep(), 2);
  static_cast<OffsetSprings*>(terms[1].get())->set_stiffness(4.0 * kStiff);
  integrator.stiffness_changed(both, t, 1);
  ExplicitVerlet whole;
  whole.topology_changed(both, t);
  EXPECT_EQ(integrator.island_stable_steps(), whole.island_stable_steps());
  EXPECT_EQ(integrator.stable_step(), whole.stable_step());
  EXPECT_EQ(integrator.island_stable_steps()[0], before[0]);
  EXPECT_NEAR(integrator.island_stable_steps()[1], 0.5 * before[1], 1e-6 * before[1]);
  EXPECT_EQ(integrator.islands_asleep(), 2);  // waking is the world's call (wake_body)
}

TEST(MultirateVerlet, a_mesh_change_of_one_body_replans_its_island_and_keeps_the_others) {
  // Body 0, the ringing light pair, gains a node (a crack duplicated a knot), which shifts the
  // sleeping heavy pair's nodes by one: body_topology_changed re-plans the light pair's island
  // as a whole re-plan would and keeps the heavy pair's plan and sleep; topology_changed would
  // have woken it.
  SimulationState both;
  std::vector<std::unique_ptr<ForceTerm>> terms;
  add_pair(both, kLightMass, kStiff, Vec3(0.0, 0.05, 0.0), terms);
  add_pair(both, kHeavyMass, kSoft, Vec3::Zero(), terms);
  both.velocities[0] = Vec3(0.0, 0.0, 0.01);
  ExplicitVerlet integrator;
  integrator.set_sleep_threshold(1e-9);
  integrator.topology_changed(both, pointers(terms));
  const std::vector<double> before = integrator.island_stable_steps();
  for (int step = 1; step <= ExplicitVerlet::kCalmStepsToSleep; ++step)
    integrator.step(both, pointers(terms), StepContext{1e-3 * step, 1e-3, step});
  ASSERT_EQ(integrator.islands_asleep(), 1);

  SimulationState grown;
  std::vector<std::unique_ptr<ForceTerm>> grown_terms;
  const auto light = both.range(both.positions, 0);
  const std::vector<Vec3> three = {light[0], light[1], light[1] + Vec3(0.01, 0.0, 0.0)};
  const std::vector<double> light_masses(3, kLightMass), heavy_masses(2, kHeavyMass);
  const std::vector<std::uint8_t> free_three(3, 0), free_two(2, 0);
  const int body = grown.add_body("pair", three, light_masses, free_three);
  grown_terms.push_back(std::make_unique<OffsetSprings>(
      body, std::vector<std::array<int, 2>>{{0, 1}, {1, 2}}, kStiff, grown));
  const auto heavy = both.range(both.positions, 1);
  const std::vector<Vec3> two = {heavy[0], heavy[1]};
  const int second = grown.add_body("pair", two, heavy_masses, free_two);
  grown_terms.push_back(std::make_unique<OffsetSprings>(
      second, std::vector<std::array<int, 2>>{{3, 4}}, kSoft, grown));
  ExplicitVerlet woken = integrator;
  integrator.body_topology_changed(grown, pointers(grown_terms), 0);
  ExplicitVerlet whole;
  whole.topology_changed(grown, pointers(grown_terms));
  EXPECT_EQ(integrator.island_stable_steps(), whole.island_stable_steps());
  EXPECT_EQ(integrator.stable_step(), whole.stable_step());
  EXPECT_EQ(integrator.island_stable_steps()[1], before[1]);
  EXPECT_EQ(integrator.islands_asleep(), 1);  // the heavy pair sleeps on at its new indices
  const std::vector<Vec3> resting(grown.positions.begin() + 3, grown.positions.end());
  integrator.step(grown, pointers(grown_terms), StepContext{0.201, 1e-3, 201});
  EXPECT_EQ(grown.positions[3], resting[0]);
  EXPECT_EQ(grown.positions[4], resting[1]);
  woken.topology_changed(grown, pointers(grown_terms));
  EXPECT_EQ(woken.islands_asleep(), 0);
}

}  // namespace viscera::sim
