#pragma once
/// The device I/O thread of a windowed session (issue 16 item 3; seed 000 §8.2: the device's
/// control loop runs at > 1 kHz, coupled to the slower virtual environment). It owns the UDP
/// bridge while it runs: it takes every pose the device sends as soon as it arrives and hands
/// the newest to the physics thread, and on its own clock (1 kHz by default) sends the force
/// of the local contact model — the proxy on the latest published surface — clamped to the
/// device's limits. Nothing it does changes the physics: the session's trace records the poses
/// the physics thread took, so the session replays bit for bit.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <thread>

#include "simulator/haptics/device_limits.h"
#include "simulator/haptics/udp_device_bridge.h"
#include "simulator/runtime/local_contact_model.h"
#include "simulator/runtime/triple_buffer.h"

namespace viscera::sim {

/// How the device loop runs.
struct DeviceLoopOptions {
  double feedback_rate = 1000.0;  ///< Hz of feedback packets (the device's servo rate)
  DeviceLimits limits;            ///< force and torque the device can render
};

/// Counters of the device loop, readable from any thread.
struct DeviceLoopCounters {
  std::atomic<long long> poses{0};              ///< poses taken from the bridge
  std::atomic<long long> feedback{0};           ///< feedback packets sent
  std::atomic<long long> late_ticks{0};         ///< feedback sent more than one period late
  std::atomic<long long> local_contact{0};      ///< feedback computed with the local proxy touching
  std::atomic<bool> real_time_priority{false};  ///< the thread got SCHED_FIFO
};

/// The thread between a device and the physics.
class HapticDeviceLoop {
 public:
  /// `bridge` must outlive the loop and is used only by the loop's thread while it runs.
  /// `surface` and `stiffness` set up the local contact model (LocalContactModel).
  HapticDeviceLoop(UdpDeviceBridge& bridge, const ContactSurface& surface, double stiffness,
                   const DeviceLoopOptions& options = {});
  ~HapticDeviceLoop();
  HapticDeviceLoop(const HapticDeviceLoop&) = delete;
  HapticDeviceLoop& operator=(const HapticDeviceLoop&) = delete;

  void start();
  /// Stops and joins the thread; safe to call twice.
  void stop();

  /// Physics thread: the newest pose since the last call, if any.
  bool newest_pose(DevicePose& out);
  /// Physics thread: the slot to fill after a step, then publish_tissue().
  TissueSnapshot& tissue_slot() { return tissue_.write_slot(); }
  void publish_tissue() { tissue_.publish(); }

  const DeviceLoopCounters& counters() const { return counters_; }
  /// SCHED_FIFO priority the loop's thread asks for (it sleeps between packets).
  static constexpr int kRealtimePriority = 20;

 private:
  void run();
  void send_feedback(const DevicePose& pose, std::uint32_t sequence);

  UdpDeviceBridge& bridge_;
  DeviceLoopOptions options_;
  LocalContactModel model_;
  TripleBuffer<DevicePose> poses_;
  TripleBuffer<TissueSnapshot> tissue_;
  DeviceLoopCounters counters_;
  std::atomic<bool> running_{false};
  std::thread thread_;
};

}  // namespace viscera::sim
