#include "simulator/runtime/realtime_loop.h"

#include <chrono>

namespace viscera::sim {

RealtimeLoop::RealtimeLoop(World& world, const RealtimeOptions& options)
    : world_(world), options_(options), bridge_(options.bridge) {}

RealtimeLoop::~RealtimeLoop() { stop(); }

void RealtimeLoop::start() {
  if (running_.exchange(true)) return;
  physics_ = std::thread([this] { physics_thread(); });
  device_ = std::thread([this] { device_thread(); });
}

void RealtimeLoop::stop() {
  running_.store(false);
  if (physics_.joinable()) physics_.join();
  if (device_.joinable()) device_.join();
}

bool RealtimeLoop::latest(SceneSnapshot& out) {
  if (!snapshots_.update()) return false;
  out = snapshots_.read_slot();
  return true;
}

void RealtimeLoop::physics_thread() {
  using clock = std::chrono::steady_clock;
  const auto step = std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(world_.time_step()));
  auto next = clock::now();
  std::uint32_t sequence = 0;
  while (running_.load(std::memory_order_relaxed)) {
    if (poses_.update()) world_.set_instrument_tip(poses_.read_slot().position);
    world_.step();
    counters_.physics_steps.fetch_add(1, std::memory_order_relaxed);

    DeviceFeedback& feedback = feedback_.write_slot();
    feedback.sequence = ++sequence;
    feedback.time_ns = static_cast<std::uint64_t>(world_.time() * 1e9);
    feedback.force = world_.instrument_force();
    feedback.torque = core::Vec3::Zero();  // a point proxy exerts no torque about its own tip
    feedback_.publish();

    SceneSnapshot& snapshot = snapshots_.write_slot();
    snapshot.steps = world_.steps();
    snapshot.time = world_.time();
    snapshot.positions.resize(world_.bodies().size());
    for (std::size_t b = 0; b < world_.bodies().size(); ++b) snapshot.positions[b].assign(world_.bodies()[b].positions().begin(),
                                                                                 world_.bodies()[b].positions().end());
    snapshot.instrument_force = world_.instrument_force();
    snapshot.instrument_in_contact = world_.instrument_in_contact();
    snapshots_.publish();

    next += step;
    const auto now = clock::now();
    if (now > next) {
      counters_.overruns.fetch_add(1, std::memory_order_relaxed);
      next = now;  // drop the lost time instead of racing to catch up
    } else {
      std::this_thread::sleep_until(next);
    }
  }
}

void RealtimeLoop::device_thread() {
  while (running_.load(std::memory_order_relaxed)) {
    // Wait at most 1 ms for a pose so feedback keeps flowing at ≥ 1 kHz either way.
    if (const auto pose = bridge_.poll(1)) {
      poses_.write_slot() = *pose;
      poses_.publish();
      counters_.poses.fetch_add(1, std::memory_order_relaxed);
    }
    if (feedback_.update()) {
      const DeviceFeedback& wanted = feedback_.read_slot();
      const ClampedFeedback clamped = clamp_to_device(wanted.force, wanted.torque, options_.tool_axis, options_.limits);
      DeviceFeedback out = wanted;
      out.force = clamped.force;
      out.torque = clamped.torque;
      out.flags = (clamped.force_limited ? kForceLimited : 0U) | (clamped.torque_limited ? kTorqueLimited : 0U);
      if (bridge_.send_feedback(out)) counters_.feedback.fetch_add(1, std::memory_order_relaxed);
    }
  }
}

}  // namespace viscera::sim
