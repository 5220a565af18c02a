// Blood particles (simulator/fluid/blood_particles.h): every drop emitted is carried, released
// into the concentration field or lost outside the grid; a particle leaves along the normal at
// its emission speed and ends up moving with the flow; past the capacity blood goes to the field;
// the same seed gives the same particles.

#include "simulator/fluid/blood_particles.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"

using namespace viscera;
using namespace viscera::sim::fluid;

namespace {

/// 20×20×20 fluid cells of 1 mm, every x face moving at `u` m/s (a uniform stream).
FlowGrid uniform_stream(double u) {
  FlowGrid grid(20, 20, 20, 0.001);
  grid.update_faces();
  for (double& face : grid.velocity(0))
    face = u;
  return grid;
}

const core::Vec3 kCentre(0.01, 0.01, 0.01);

}  // namespace

TEST(BloodParticles, every_drop_is_carried_released_or_lost) {
  const FlowGrid grid = uniform_stream(0.004);
  ConcentrationField field(grid);
  BloodParticleSettings settings;
  BloodParticles blood(settings, 7);
  double handed_in = 0.0;
  for (int step = 0; step < 400; ++step) {
    const double volume = 0.37e-9 * (1 + step % 3);  // not whole particles
    blood.emit(kCentre, core::Vec3(0, 0, 1), 0.01, volume, grid, field);
    handed_in += volume;
    blood.advance(grid, nullptr, field, 0.01);
    // To rounding: the books add some 10⁵ small releases (one lost particle would be 1e-3).
    const double booked = blood.carried_volume() + blood.released_volume() + blood.lost_volume();
    ASSERT_NEAR(booked, blood.emitted_volume(), 1e-10 * handed_in);
    ASSERT_NEAR(blood.emitted_volume() + blood.pending_volume(), handed_in, 1e-12 * handed_in);
    ASSERT_LT(blood.pending_volume(), settings.particle_volume);
  }
  EXPECT_NEAR(field.total_volume(grid), blood.released_volume(), 1e-10 * handed_in);
  EXPECT_GT(blood.released_volume(), 0.0);
  EXPECT_GT(blood.lost_volume(), 0.0);  // the stream carries some past the grid's x end
  // Particles live three seconds: after four, the first ones are gone.
  EXPECT_LT(blood.size(), static_cast<std::size_t>(handed_in / settings.particle_volume));
  for (std::size_t i = 0; i < blood.size(); ++i)
    EXPECT_LT(blood.stage(i), 1.0);
}

TEST(BloodParticles, a_particle_leaves_along_the_normal_and_then_moves_with_the_flow) {
  const double u = 0.002;
  const FlowGrid grid = uniform_stream(u);
  ConcentrationField field(grid);
  BloodParticleSettings settings;
  settings.spread = 0.0;
  settings.lifetime = 20.0;  // outlives the ten time constants below
  BloodParticles blood(settings, 1);
  const double speed = 0.02;
  blood.emit(kCentre, core::Vec3(0, 0, 2), speed, settings.particle_volume, grid, field);
  ASSERT_EQ(blood.size(), 1u);

  const double dt = 1e-3;
  blood.advance(grid, nullptr, field, dt);
  core::Vec3 moved = blood.positions()[0] - kCentre;
  const double w = std::exp(-dt / settings.emitter_time_constant);
  EXPECT_NEAR(moved.z(), dt * w * speed, 1e-15);
  EXPECT_NEAR(moved.x(), dt * (1 - w) * u, 1e-15);

  // Ten emitter time constants later the emitter's push is spent.
  for (double t = dt; t < 10 * settings.emitter_time_constant; t += dt)
    blood.advance(grid, nullptr, field, dt);
  const core::Vec3 before = blood.positions()[0];
  blood.advance(grid, nullptr, field, dt);
  moved = blood.positions()[0] - before;
  EXPECT_NEAR(moved.x(), dt * u, 1e-4 * dt * u);
  EXPECT_LT(std::abs(moved.z()), 1e-4 * dt * speed);
  // The distance risen is the emitter's integral, speed · τ_e (1 − e^{−t/τ_e})
  // (explicit Euler sums it a first-order step short: dt / 2τ_e ≈ 0.2 %).
  const double rise = speed * settings.emitter_time_constant;
  EXPECT_NEAR(before.z() - kCentre.z(), rise, 5e-3 * rise);
}

TEST(BloodParticles, past_the_capacity_blood_goes_straight_to_the_field) {
  const FlowGrid grid = uniform_stream(0.0);
  ConcentrationField field(grid);
  BloodParticleSettings settings;
  settings.capacity = 50;
  BloodParticles blood(settings, 3);
  blood.emit(kCentre, core::Vec3(1, 0, 0), 0.0, 80.5 * settings.particle_volume, grid, field);
  EXPECT_EQ(blood.size(), 50u);
  EXPECT_NEAR(field.total_volume(grid), 30 * settings.particle_volume, 1e-20);
  EXPECT_NEAR(blood.released_volume(), 30 * settings.particle_volume, 1e-20);
}

TEST(BloodParticles, the_same_seed_gives_the_same_particles_and_bad_settings_are_refused) {
  const FlowGrid grid = uniform_stream(0.003);
  auto run = [&](std::uint64_t seed) {
    ConcentrationField field(grid);
    BloodParticles blood(BloodParticleSettings{}, seed);
    for (int step = 0; step < 50; ++step) {
      blood.emit(kCentre, core::Vec3(0, 1, 0), 0.01, 1e-9, grid, field);
      blood.advance(grid, nullptr, field, 0.01);
    }
    return blood.positions();
  };
  EXPECT_EQ(run(11), run(11));
  EXPECT_NE(run(11), run(12));

  BloodParticleSettings bad;
  bad.lifetime = 0.0;
  EXPECT_THROW(BloodParticles(bad, 1), core::UsageError);
}

TEST(BloodParticles, a_spurt_at_the_wall_stops_at_it_and_keeps_its_blood_in_the_fluid) {
  // Tissue from x = 15 mm on; a fast spurt towards it, advanced in 40 ms steps (12 cells a step
  // at its birth speed): no particle enters the tissue and no blood is lost into it.
  FlowGrid grid(20, 20, 20, 0.001);
  for (int k = 0; k < 20; ++k)
    for (int j = 0; j < 20; ++j)
      for (int i = 15; i < 20; ++i)
        grid.set_cell(i, j, k, FlowCell::Solid);
  grid.update_faces();
  ConcentrationField field(grid);
  BloodParticles blood(BloodParticleSettings{}, 3);
  for (int step = 0; step < 50; ++step) {
    if (step < 10) blood.emit(kCentre, core::Vec3(1, 0, 0), 0.3, 2e-9, grid, field);
    blood.advance(grid, nullptr, field, 0.04);
    for (const core::Vec3& p : blood.positions()) {
      ASSERT_LT(p.x(), 0.015);
      ASSERT_GT(p.x(), kCentre.x());  // it did leave along the normal
    }
  }
  EXPECT_EQ(blood.lost_volume(), 0.0);
  EXPECT_NEAR(field.total_volume(grid), blood.released_volume(), 1e-12 * blood.emitted_volume());
  EXPECT_NEAR(blood.carried_volume() + blood.released_volume(), blood.emitted_volume(),
              1e-12 * blood.emitted_volume());
}
