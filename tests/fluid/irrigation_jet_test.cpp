// The irrigation jet of seed 001 §4.3 (simulator/fluid/irrigation_jet.h): drops leave the tip
// at the rate and speed of a real cannula, fly the ballistic parabola, hit and rebound by eq. 5
// with the eq. 4 push on the hit knots, and land in the pool; volume is conserved through
// irrigation and suction.

#include "simulator/fluid/irrigation_jet.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "simulator/fluid/jet_impact.h"

using namespace viscera;
using namespace viscera::sim::fluid;

namespace {

const core::Vec3 kGravity(0.0, 0.0, -9.81);
constexpr double kStep = 1e-3;

/// A pool 1 m below the origin: nothing lands in it during the tests of flight.
FluidPool deep_pool() {
  return FluidPool(core::Vec3(0, 0, -1.0), kGravity);
}

/// The plane through `point` with unit normal `normal`, as body 0's triangle of knots 0, 1, 2.
SurfaceQuery plane(const core::Vec3& point, const core::Vec3& normal) {
  return
      [point, normal](const core::Vec3& from, const core::Vec3& to) -> std::optional<SurfaceHit> {
        const double a = (from - point).dot(normal), b = (to - point).dot(normal);
        if (a < 0.0 || b >= 0.0) return std::nullopt;
        SurfaceHit hit;
        hit.fraction = a / (a - b);
        hit.point = from + hit.fraction * (to - from);
        hit.normal = normal;
        hit.body = 0;
        hit.nodes = {0, 1, 2};
        hit.weights = core::Vec3(0.2, 0.3, 0.5);
        return hit;
      };
}

}  // namespace

TEST(IrrigationJet, drops_leave_the_tip_at_the_cannulas_rate_and_speed) {
  IrrigationJet jet;
  // 10 ml/s through a 4 mm bore: ≈ 0.8 m/s.
  EXPECT_NEAR(jet.options().rate / (M_PI * 0.002 * 0.002), jet.options().speed, 0.01);
  const core::Vec3 axis = core::Vec3(1.0, 0.0, -1.0).normalized();
  for (int step = 0; step < 250; ++step)
    jet.emit(core::Vec3::Zero(), 3.0 * axis, kStep);  // the direction's length does not matter
  EXPECT_EQ(jet.drops().size(), 250u);                // one 0.01 ml drop per 1 ms
  EXPECT_NEAR(jet.emitted_volume(), 2.5e-6, 1e-15);
  EXPECT_NEAR((jet.drops()[0].velocity - 0.8 * axis).norm(), 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(jet.drop_mass(), 1e-5);  // 10 mg
}

TEST(IrrigationJet, a_drop_in_flight_follows_the_ballistic_parabola) {
  IrrigationJet jet;
  FluidPool pool = deep_pool();
  const core::Vec3 tip(0.01, -0.02, 0.03), axis = core::Vec3(0.6, 0.0, 0.8);
  jet.emit(tip, axis, kStep);
  ASSERT_EQ(jet.drops().size(), 1u);
  const core::Vec3 v0 = 0.8 * axis;
  for (int step = 1; step <= 200; ++step) {
    EXPECT_TRUE(jet.step(kStep, kGravity, plane(core::Vec3(0, 0, -0.5), core::Vec3::UnitZ()), pool)
                    .empty());
    const double t = step * kStep;
    const core::Vec3 expected = tip + v0 * t + 0.5 * kGravity * t * t;
    ASSERT_EQ(jet.drops().size(), 1u);
    EXPECT_NEAR((jet.drops()[0].position - expected).norm(), 0.0, 1e-12) << "t = " << t;
    EXPECT_NEAR((jet.drops()[0].velocity - (v0 + kGravity * t)).norm(), 0.0, 1e-12);
  }
  EXPECT_EQ(pool.contents().total(), 0.0);
}

TEST(IrrigationJet, a_hit_rebounds_by_eq5_and_pushes_the_hit_knots_by_eq4) {
  IrrigationJet jet;
  FluidPool pool = deep_pool();
  const JetOptions& o = jet.options();
  // Sideways at 0.8 m/s from 5 cm above the plane z = 0: it lands after ≈ 0.1 s.
  jet.emit(core::Vec3(0, 0, 0.05), core::Vec3::UnitX(), kStep);
  const SurfaceQuery floor = plane(core::Vec3::Zero(), core::Vec3::UnitZ());
  std::vector<JetImpact> impacts;
  int steps = 0;
  while (impacts.empty() && steps++ < 500)
    impacts = jet.step(kStep, kGravity, floor, pool);
  ASSERT_EQ(impacts.size(), 1u);
  ASSERT_EQ(jet.drops().size(), 1u);
  const JetDrop& drop = jet.drops()[0];
  EXPECT_EQ(drop.bounces, 1);
  EXPECT_EQ(jet.splashes(), 0);  // ≈ 1.2 m/s onto the plane: below the splashing threshold
  EXPECT_NEAR(drop.position.z(), o.offset, 1e-15);  // put just off the surface
  // Eq. 5: the slide (x) keeps 1 − µ of 0.8 m/s; the normal speed reverses to ε of the fall
  // speed at impact, √(2 g h) to the chord's accuracy.
  EXPECT_NEAR(drop.velocity.x(), (1.0 - o.friction) * 0.8, 1e-12);
  EXPECT_NEAR(drop.velocity.z(), o.elasticity * std::sqrt(2.0 * 9.81 * 0.05), 0.01);
  // Eq. 4 with the velocity before the hit that eq. 5 implies.
  const core::Vec3 v_old(drop.velocity.x() / (1.0 - o.friction), 0.0,
                         -drop.velocity.z() / o.elasticity);
  const core::Vec3 f = impacts[0].force;
  EXPECT_NEAR(f.normalized().dot(v_old.normalized()), 1.0, 1e-12);
  EXPECT_NEAR(
      f.norm(),
      jet.drop_mass() * o.impact_scale * (v_old.squaredNorm() - drop.velocity.squaredNorm()),
      1e-12 * f.norm());
  EXPECT_LT(f.z(), 0.0);  // pushes the tissue down, the way the drop came
  EXPECT_EQ(impacts[0].nodes, (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(impacts[0].weights, core::Vec3(0.2, 0.3, 0.5));
  // It bounces on until it is slow or has hit three times, then runs off to the pool.
  for (int step = 0; step < 2000 && !jet.drops().empty(); ++step)
    jet.step(kStep, kGravity, floor, pool);
  EXPECT_TRUE(jet.drops().empty());
  EXPECT_NEAR(pool.contents().water, o.drop_volume, 1e-20);
}

TEST(IrrigationJet, a_fast_drop_splashes_into_four_quarters_that_keep_its_momentum) {
  IrrigationJet jet;
  const JetOptions& o = jet.options();
  // Cossali's K for a 0.01 ml drop: ≈ 490 at 1 m/s, past 2100 above ≈ 2.1 m/s (K ∝ v²).
  EXPECT_GT(jet.splash_number(4, 1.0), 400.0);
  EXPECT_LT(jet.splash_number(4, 1.0), 600.0);
  EXPECT_NEAR(jet.splash_number(4, 2.0) / jet.splash_number(4, 1.0), 4.0, 1e-12);
  EXPECT_GT(jet.splash_number(4, 2.2), o.splash_threshold);
  // Straight down from 50 cm: ≈ 3.2 m/s at the plane z = 0.
  FluidPool pool = deep_pool();
  jet.emit(core::Vec3(0, 0, 0.5), core::Vec3(0, 0, -1), kStep);
  const SurfaceQuery floor = plane(core::Vec3::Zero(), core::Vec3::UnitZ());
  std::vector<JetImpact> impacts;
  for (int step = 0; step < 500 && impacts.empty(); ++step)
    impacts = jet.step(kStep, kGravity, floor, pool);
  ASSERT_EQ(impacts.size(), 1u);
  EXPECT_EQ(jet.splashes(), 1);
  ASSERT_EQ(jet.drops().size(), 4u);
  core::Vec3 momentum = core::Vec3::Zero();
  for (const JetDrop& d : jet.drops()) {
    EXPECT_EQ(d.quarters, 1);
    EXPECT_GT(d.velocity.z(), 0.0);  // up, off the surface
    momentum += jet.drop_mass(d.quarters) * d.velocity;
  }
  // The four throws cancel: together they carry the whole drop's rebound, ε of its fall.
  const double fall = std::sqrt(impacts[0].force.norm() / (jet.drop_mass() * o.impact_scale *
                                                           (1.0 - o.elasticity * o.elasticity)));
  EXPECT_NEAR(momentum.x(), 0.0, 1e-15);
  EXPECT_NEAR(momentum.y(), 0.0, 1e-15);
  EXPECT_NEAR(momentum.z(), jet.drop_mass() * o.elasticity * fall, 1e-12 * jet.drop_mass());
  EXPECT_NEAR(fall, std::sqrt(0.64 + 2.0 * 9.81 * 0.5), 0.02);
  EXPECT_NEAR(jet.in_flight_volume(), o.drop_volume, 1e-20);
  // The quarters do not splash again; all of the drop ends in the pool.
  for (int step = 0; step < 3000 && !jet.drops().empty(); ++step) {
    jet.step(kStep, kGravity, floor, pool);
    EXPECT_NEAR(jet.in_flight_volume() + pool.contents().water, o.drop_volume, 1e-20);
  }
  EXPECT_EQ(jet.splashes(), 1);
  EXPECT_TRUE(jet.drops().empty());
  EXPECT_NEAR(pool.contents().water, o.drop_volume, 1e-20);
}

TEST(IrrigationJet, irrigation_then_suction_leaves_the_pool_equal_to_irrigated_less_suctioned) {
  IrrigationJet jet;
  FluidPool pool(core::Vec3(0, 0, -0.06), kGravity);
  // The jet 4 cm above a slope of 30° that drops towards the pool 6 cm down.
  const SurfaceQuery slope =
      plane(core::Vec3(0, 0, 0), core::Vec3(std::sin(M_PI / 6.0), 0.0, std::cos(M_PI / 6.0)));
  const core::Vec3 tip(-0.02, 0.0, 0.04), axis = core::Vec3(0.3, 0.0, -1.0).normalized();
  const SuctionOptions suction;
  int impacts = 0;
  const auto balance = [&] {
    // Everything irrigated is in flight, in the pool, or was suctioned.
    EXPECT_NEAR(jet.emitted_volume(),
                jet.in_flight_volume() + pool.contents().water + pool.suctioned().water, 1e-18);
    EXPECT_NEAR(jet.landed_volume(), pool.received().water, 1e-18);
  };
  for (int step = 0; step < 1000; ++step) {  // irrigate 1 s
    jet.emit(tip, axis, kStep);
    impacts += static_cast<int>(jet.step(kStep, kGravity, slope, pool).size());
    balance();
  }
  EXPECT_NEAR(jet.emitted_volume(), 10e-6, 1e-15);  // 10 ml
  EXPECT_GT(impacts, 900);                          // the jet hits the slope
  EXPECT_GT(jet.in_flight_volume(), 0.0);
  EXPECT_GT(pool.contents().water, 5e-6);
  // Suction at the pool's surface while the last drops still land.
  for (int step = 0; step < 400; ++step) {
    jet.step(kStep, kGravity, slope, pool);
    pool.suck(pool.surface_point(core::Vec3(0.05, 0, 0)), suction, kStep);
    balance();
  }
  EXPECT_TRUE(jet.drops().empty());
  EXPECT_NEAR(pool.suctioned().water, 400 * kStep * suction.rate, 1e-15);  // 6 ml
  EXPECT_NEAR(pool.contents().water, 10e-6 - 6e-6, 1e-15);
  EXPECT_NEAR(pool.height(), 4e-6 / pool.area(), 1e-15);
}

TEST(IrrigationJet, the_same_inputs_give_the_same_drops_bit_for_bit) {
  const auto run = [] {
    IrrigationJet jet;
    FluidPool pool(core::Vec3(0, 0, -0.06), kGravity);
    const SurfaceQuery slope = plane(core::Vec3::Zero(), core::Vec3(0.3, 0.1, 1.0).normalized());
    for (int step = 0; step < 300; ++step) {
      jet.emit(core::Vec3(0, 0, 0.03), core::Vec3(0.2, 0.1, -1.0), kStep);
      jet.step(kStep, kGravity, slope, pool);
    }
    return std::make_pair(jet.drops(), pool.contents().water);
  };
  const auto a = run(), b = run();
  ASSERT_EQ(a.first.size(), b.first.size());
  for (std::size_t i = 0; i < a.first.size(); ++i) {
    EXPECT_EQ(a.first[i].position, b.first[i].position);
    EXPECT_EQ(a.first[i].velocity, b.first[i].velocity);
  }
  EXPECT_EQ(a.second, b.second);
}

TEST(IrrigationJet, refuses_unusable_options_and_a_zero_direction) {
  const auto with = [](auto change) {
    JetOptions o;
    change(o);
    return o;
  };
  EXPECT_THROW(IrrigationJet(with([](JetOptions& o) { o.rate = 0.0; })), core::InputError);
  EXPECT_THROW(IrrigationJet(with([](JetOptions& o) { o.drop_volume = -1e-8; })), core::InputError);
  EXPECT_THROW(IrrigationJet(with([](JetOptions& o) { o.elasticity = 1.5; })), core::InputError);
  EXPECT_THROW(IrrigationJet(with([](JetOptions& o) { o.friction = -0.1; })), core::InputError);
  EXPECT_THROW(IrrigationJet(with([](JetOptions& o) { o.max_bounces = -1; })), core::InputError);
  IrrigationJet jet;
  EXPECT_THROW(jet.emit(core::Vec3::Zero(), core::Vec3::Zero(), kStep), core::InputError);
  EXPECT_THROW(jet.emit(core::Vec3(NAN, 0, 0), core::Vec3::UnitZ(), kStep), core::InputError);
  EXPECT_TRUE(jet.drops().empty());
}
