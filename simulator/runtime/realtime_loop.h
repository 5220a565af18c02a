#pragma once
/// The interactive runtime (DESIGN.md §5): physics at a fixed step on its own thread, the haptic
/// device on another, and snapshots handed between them and to the view through lock-free
/// triple buffers. The deterministic mode of sessions and replays is World::step() on one
/// thread; this loop is for a trainee at a device, where wall-clock pacing matters.

#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

#include "simulator/haptics/device_limits.h"
#include "simulator/haptics/udp_device_bridge.h"
#include "simulator/runtime/triple_buffer.h"
#include "simulator/world/world.h"

namespace viscera::sim {

/// What the view sees of the world: positions of every body at one physics step.
struct SceneSnapshot {
  long long steps = 0;
  double time = 0.0;                                ///< s
  std::vector<std::vector<core::Vec3>> positions;   ///< per body, m
  core::Vec3 instrument_force = core::Vec3::Zero(); ///< N, before the device limits
  bool instrument_in_contact = false;
};

/// How the loop runs.
struct RealtimeOptions {
  BridgeOptions bridge;           ///< where the device bridge listens
  DeviceLimits limits;            ///< force and torque the device can render
  core::Vec3 tool_axis = core::Vec3::UnitZ();  ///< for splitting roll from pitch/yaw torque
};

/// Counters of the loop, readable from any thread.
struct RealtimeCounters {
  std::atomic<long long> physics_steps{0};
  std::atomic<long long> overruns{0};   ///< steps that started late (the physics fell behind)
  std::atomic<long long> poses{0};      ///< device poses handed to the physics
  std::atomic<long long> feedback{0};   ///< feedback packets sent to the device
};

/// Runs `world` in real time with an instrument driven by a UDP haptic device.
class RealtimeLoop {
 public:
  /// `world` must have an instrument attached (World::attach_instrument) and outlive the loop.
  RealtimeLoop(World& world, const RealtimeOptions& options = {});
  ~RealtimeLoop();
  RealtimeLoop(const RealtimeLoop&) = delete;
  RealtimeLoop& operator=(const RealtimeLoop&) = delete;

  /// UDP port the device should send its poses to.
  std::uint16_t device_port() const { return bridge_.port(); }
  void start();
  /// Stops both threads; safe to call twice.
  void stop();

  /// Copies the newest snapshot into `out`; false when nothing new was published since the
  /// last call. Call from one thread only (the view).
  bool latest(SceneSnapshot& out);

  const RealtimeCounters& counters() const { return counters_; }
  const BridgeCounters& bridge_counters() const { return bridge_.counters(); }

 private:
  void physics_thread();
  void device_thread();

  World& world_;
  RealtimeOptions options_;
  UdpDeviceBridge bridge_;
  TripleBuffer<DevicePose> poses_;
  TripleBuffer<DeviceFeedback> feedback_;
  TripleBuffer<SceneSnapshot> snapshots_;
  RealtimeCounters counters_;
  std::atomic<bool> running_{false};
  std::thread physics_, device_;
};

}  // namespace viscera::sim
