#include "simulator/runtime/realtime_loop.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "core/error.h"
#include "simulator/haptics/simulated_device.h"
#include "tests/simulator/sim_fixtures.h"

namespace viscera::sim {
namespace {

/// A 4 × 4 × 2 cm soft block with its bottom held, top face at z = 2 cm.
core::Scenario soft_block() {
  core::Scenario scenario = viscera::testing::held_soft_block();
  scenario.session.gravity = core::Vec3::Zero();
  return scenario;
}

struct Pair {
  long long a = 0, b = 0;  // always written equal: a torn read would show a ≠ b
};

TEST(TripleBuffer, reader_sees_only_whole_and_ever_newer_values) {
  TripleBuffer<Pair> buffer;
  EXPECT_FALSE(buffer.update());
  constexpr long long kCount = 200000;
  std::thread writer([&] {
    for (long long i = 1; i <= kCount; ++i) {
      buffer.write_slot() = {i, i};
      buffer.publish();
    }
  });
  long long last = 0;
  while (last < kCount) {
    if (!buffer.update()) continue;
    const Pair& p = buffer.read_slot();
    ASSERT_EQ(p.a, p.b);
    ASSERT_GT(p.a, last);
    last = p.a;
  }
  writer.join();
  EXPECT_EQ(last, kCount);
}

TEST(WorldInstrument, pressing_into_tissue_feels_an_outward_force_and_dents_it) {
  World world(soft_block());
  world.attach_instrument(0, 100.0, {0.02, 0.021, 0.03});
  world.set_instrument_tip({0.02, 0.021, 0.015});  // 5 mm below the top face
  for (int s = 0; s < 300; ++s)
    world.step();
  ASSERT_TRUE(world.instrument_in_contact());
  const core::Vec3 force = world.instrument_force();
  EXPECT_GT(force.z(), 0.0);
  // Mostly upward; the dent around the tool tilts the touched triangle a little.
  EXPECT_LT(std::abs(force.x()) + std::abs(force.y()), 0.25 * force.z());
  EXPECT_GT(world.bodies()[0].max_displacement(), 1e-4);  // the tissue gives way under the tool
  EXPECT_THROW(world.attach_instrument(3, 100.0, core::Vec3::Zero()), core::UsageError);
}

TEST(RealtimeLoop, a_device_on_loopback_drives_the_tool_and_feels_the_tissue) {
  World world(soft_block());
  world.attach_instrument(0, 200.0, {0.02, 0.021, 0.04});
  RealtimeLoop loop(world);
  SimulatedDevice device(loop.device_port());
  loop.start();
  DevicePose pose;
  std::optional<DeviceFeedback> pressed;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  for (std::uint32_t i = 1; std::chrono::steady_clock::now() < deadline; ++i) {
    pose.sequence = i;
    pose.position = {0.02, 0.021, std::max(0.014, 0.04 - 0.0002 * i)};  // down to 6 mm deep
    device.send(pose);
    if (auto feedback = device.receive(2); feedback && feedback->force.z() > 0.1) {
      pressed = feedback;
      break;
    }
  }
  SceneSnapshot snapshot;
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const bool fresh = loop.latest(snapshot);
  loop.stop();
  ASSERT_TRUE(pressed.has_value()) << "no force came back through the bridge";
  EXPECT_LE(pressed->force.norm(), 2.0 + 1e-12);  // within the device's limit
  EXPECT_GT(loop.counters().physics_steps.load(), 10);
  EXPECT_GT(loop.counters().poses.load(), 0);
  EXPECT_GT(loop.counters().feedback.load(), 0);
  ASSERT_TRUE(fresh);
  EXPECT_EQ(snapshot.positions.size(), 1u);
  EXPECT_GT(snapshot.steps, 0);
}

}  // namespace
}  // namespace viscera::sim
