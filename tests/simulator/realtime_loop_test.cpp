#include "simulator/runtime/realtime_loop.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "core/error.h"
#include "simulator/haptics/simulated_device.h"
#include "simulator/input/device_input.h"
#include "simulator/runtime/local_contact_model.h"
#include "simulator/session/headless_session.h"
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

/// A square sheet of two triangles at height z (nodes 0–3), facing +z.
ContactSurface square_surface() {
  return ContactSurface({{0, 1, 2}, {0, 2, 3}});
}

std::vector<core::Vec3> square_at(double z) {
  return {{-0.01, -0.01, z}, {0.01, -0.01, z}, {0.01, 0.01, z}, {-0.01, 0.01, z}};
}

TEST(LocalContactModel, the_proxy_on_the_latest_surface_pushes_the_tip_out_by_its_depth) {
  const ContactSurface surface = square_surface();
  ASSERT_EQ(surface.nodes().size(), 4u);
  LocalContactModel model(surface, 200.0);
  EXPECT_EQ(model.force_at({0.0, 0.0, 0.005}), core::Vec3::Zero());  // no tissue yet
  TissueSnapshot tissue;
  tissue.surface = square_at(0.0);
  model.set_tissue(tissue);
  EXPECT_EQ(model.force_at({0.001, 0.0, 0.004}), core::Vec3::Zero());  // above: free
  const core::Vec3 pressed = model.force_at({0.001, 0.0, -0.003});     // 3 mm in
  ASSERT_TRUE(model.in_contact());
  EXPECT_NEAR(pressed.z(), 200.0 * 0.003, 1e-9);
  EXPECT_NEAR(pressed.x(), 0.0, 1e-12);
  // The physics moved the surface up by 1 mm: the same tip is 4 mm deep at once.
  TissueSnapshot lifted;
  lifted.surface = square_at(0.001);
  model.set_tissue(lifted);
  EXPECT_NEAR(model.force_at({0.001, 0.0, -0.003}).z(), 200.0 * 0.004, 1e-9);
  EXPECT_EQ(model.force_at({0.001, 0.0, 0.003}), core::Vec3::Zero());  // pulled out
  EXPECT_FALSE(model.in_contact());
}

TEST(LocalContactModel, without_a_surface_it_holds_the_physics_force) {
  LocalContactModel model(ContactSurface(), 200.0);
  TissueSnapshot tissue;
  tissue.force = {0.0, 0.3, 0.0};
  model.set_tissue(tissue);
  EXPECT_EQ(model.force_at({0.0, 0.0, 0.0}), tissue.force);
}

TEST(RealtimeLoop, a_threaded_device_session_replays_bit_identically_headless) {
  const core::Scenario scenario = soft_block();
  InstrumentState start;
  start.tip = {0.02, 0.021, 0.04};  // 2 cm above the top face
  DeviceInput input({"127.0.0.1", 0}, start);
  HeadlessRunOptions options;
  options.duration = 0.8;
  options.record_inputs = true;
  options.instrument_stiffness = 200.0;
  const LiveInstrument instrument(input);
  HeadlessRunOptions live = options;
  live.instrument = &instrument;
  SessionRunner runner(scenario, live);
  RealtimeLoop loop(runner, &input, nullptr);
  SimulatedDevice device(input.port());

  // The device presses 6 mm into the block at 1 kHz while the session runs in real time.
  std::atomic<long long> feedback{0};
  std::atomic<double> max_force{0.0};
  std::thread receiver([&] {
    while (!loop.finished()) {
      if (const auto f = device.receive(2)) {
        feedback.fetch_add(1);
        if (f->force.norm() > max_force.load()) max_force.store(f->force.norm());
      }
    }
  });
  loop.start();
  const auto began = std::chrono::steady_clock::now();
  for (std::uint32_t i = 1; !loop.finished(); ++i) {
    std::this_thread::sleep_until(began + std::chrono::microseconds(1000 * i));
    DevicePose pose;
    pose.sequence = i;
    pose.position = {0.02, 0.021, std::max(0.014, 0.04 - 0.0001 * i)};
    device.send(pose);
  }
  loop.join();
  receiver.join();
  const SessionReport report = runner.finish();
  ASSERT_EQ(report.end_reason, "duration");
  EXPECT_EQ(loop.counters().physics_steps.load(), report.steps);
  EXPECT_GT(report.metrics.contact_time(), 0.0);  // the tool reached the tissue
  EXPECT_GT(feedback.load(), 100);
  EXPECT_GT(max_force.load(), 0.1);
  EXPECT_LE(max_force.load(), 2.0 + 1e-12);  // within the device's limit
  EXPECT_EQ(input.loop(), nullptr);          // the device loop stopped with the session
  EXPECT_GT(loop.wall_time(), 0.7);          // paced by the wall clock, not run at full speed

  // The trace's inputs replay on one thread to the same state, bit for bit.
  const RecordedInput recorded(report.inputs);
  HeadlessRunOptions replay = options;
  replay.instrument = &recorded;
  const SessionReport again = run_headless(scenario, replay);
  EXPECT_EQ(again.steps, report.steps);
  EXPECT_EQ(again.checkpoints, report.checkpoints);
  EXPECT_EQ(again.final_state_hash, report.final_state_hash);
}

TEST(RealtimeLoop, an_end_request_stops_the_session_and_a_script_drives_it_on_time) {
  const core::Scenario scenario = soft_block();
  InstrumentState above;
  above.tip = {0.02, 0.021, 0.1};  // 8 cm above the block, touching nothing
  const RecordedInput still({{0, above}});
  HeadlessRunOptions options;
  options.duration = 30.0;
  options.instrument = &still;
  SessionRunner runner(scenario, options);
  RealtimeLoop loop(runner, nullptr, &still);
  loop.start();
  const SessionSnapshot* seen = nullptr;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (seen == nullptr && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    seen = loop.latest();
  }
  ASSERT_NE(seen, nullptr);
  EXPECT_EQ(seen->bodies.size(), 1u);
  EXPECT_EQ(seen->bodies[0].name, "block");
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  loop.request_end("abort", "the test ended the session");
  loop.join();
  EXPECT_TRUE(loop.finished());
  const SessionReport report = runner.finish();
  EXPECT_EQ(report.end_reason, "abort");
  // Real time: about 0.2–0.3 s simulated, nowhere near the 30 s a headless run would do.
  EXPECT_GT(report.simulated_time, 0.1);
  EXPECT_LT(report.simulated_time, 5.0);
  const SessionSnapshot* last = loop.latest();
  ASSERT_NE(last, nullptr);
  EXPECT_EQ(last->ended, "abort");
}

}  // namespace
}  // namespace viscera::sim
