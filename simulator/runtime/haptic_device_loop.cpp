#include "simulator/runtime/haptic_device_loop.h"

#include <pthread.h>
#include <sched.h>

#include <Eigen/Geometry>

namespace viscera::sim {

namespace {

/// The shaft direction of a pose: q·ẑ (a zero quaternion counts as the identity).
core::Vec3 tool_axis(const DevicePose& pose) {
  const auto& o = pose.orientation;
  Eigen::Quaterniond q(o[0], o[1], o[2], o[3]);
  if (q.norm() < 1e-12) return core::Vec3::UnitZ();
  return q.normalized() * core::Vec3(core::Vec3::UnitZ());
}

}  // namespace

HapticDeviceLoop::HapticDeviceLoop(UdpDeviceBridge& bridge, const ContactSurface& surface,
                                   double stiffness, const DeviceLoopOptions& options)
    : bridge_(bridge), options_(options), model_(surface, stiffness) {}

HapticDeviceLoop::~HapticDeviceLoop() {
  stop();
}

void HapticDeviceLoop::start() {
  if (running_.exchange(true)) return;
  thread_ = std::thread([this] { run(); });
}

void HapticDeviceLoop::stop() {
  running_.store(false);
  if (thread_.joinable()) thread_.join();
}

bool HapticDeviceLoop::newest_pose(DevicePose& out) {
  if (!poses_.update()) return false;
  out = poses_.read_slot();
  return true;
}

void HapticDeviceLoop::send_feedback(const DevicePose& pose, std::uint32_t sequence) {
  if (tissue_.update()) model_.set_tissue(tissue_.read_slot());
  const core::Vec3 force = model_.force_at(pose.position);
  const ClampedFeedback clamped =
      clamp_to_device(force, core::Vec3::Zero(), tool_axis(pose), options_.limits);
  DeviceFeedback feedback;
  feedback.sequence = sequence;
  feedback.time_ns = pose.time_ns;  // echoes the pose it answers, for the device's latency
  feedback.force = clamped.force;
  feedback.torque = clamped.torque;
  feedback.flags =
      (clamped.force_limited ? kForceLimited : 0U) | (clamped.torque_limited ? kTorqueLimited : 0U);
  if (bridge_.send_feedback(feedback)) {
    counters_.feedback.fetch_add(1, std::memory_order_relaxed);
    if (model_.in_contact()) counters_.local_contact.fetch_add(1, std::memory_order_relaxed);
  }
}

void HapticDeviceLoop::run() {
  // A haptic servo loop wants its wake-ups on time (seed 000 §8.2 runs it under a real-time
  // OS): ask for a real-time priority. The thread sleeps between packets, so it never starves
  // the others; without the privilege it runs at normal priority.
  sched_param priority{};
  priority.sched_priority = kRealtimePriority;
  counters_.real_time_priority.store(pthread_setschedparam(pthread_self(), SCHED_FIFO, &priority) ==
                                     0);
  using clock = std::chrono::steady_clock;
  const auto period = std::chrono::duration_cast<clock::duration>(
      std::chrono::duration<double>(1.0 / options_.feedback_rate));
  auto deadline = clock::now() + period;
  DevicePose pose;
  bool have_pose = false;
  std::uint32_t sequence = 0;
  while (running_.load(std::memory_order_relaxed)) {
    // Until the next feedback is due, take poses the moment they arrive.
    const auto now = clock::now();
    if (now < deadline &&
        !bridge_.wait(std::chrono::duration_cast<std::chrono::microseconds>(deadline - now))) {
      // Timed out, or the socket reported an error without data: never spin at this priority.
      std::this_thread::sleep_until(deadline);
    }
    if (const auto newest = bridge_.poll(0)) {
      pose = *newest;
      have_pose = true;
      poses_.write_slot() = pose;
      poses_.publish();
      counters_.poses.fetch_add(1, std::memory_order_relaxed);
    }
    const auto after = clock::now();
    if (after < deadline) continue;
    if (have_pose) send_feedback(pose, ++sequence);
    if (after - deadline > period) counters_.late_ticks.fetch_add(1, std::memory_order_relaxed);
    deadline += period;
    // After a long stall (the process was descheduled), start the clock afresh rather than
    // sending a burst to catch up.
    if (after - deadline > 4 * period) deadline = after + period;
  }
}

}  // namespace viscera::sim
