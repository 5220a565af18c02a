#pragma once
/// One haptic device's link to a session (issue 8 item 7, issue 16 item 3, issue 19 §7): its
/// UDP bridge, the device loop that takes over the bridge's I/O in a threaded session, the
/// feedback sequence and the counters. The same link serves the working port's device
/// (DeviceInput) and the second port's (TwoHandedInput); what differs between the two hands —
/// which tool's state a pose sets, which force goes back, which surface the local contact model
/// walks on — is the owner's business: it hands the link a DeviceStep after every physics step.

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "simulator/haptics/device_limits.h"
#include "simulator/haptics/device_packets.h"
#include "simulator/haptics/udp_device_bridge.h"
#include "simulator/runtime/haptic_device_loop.h"
#include "simulator/runtime/local_contact_model.h"

namespace viscera::sim {

/// What one physics step left on the device's tool.
struct DeviceStep {
  long long steps = 0;                    ///< physics steps so far
  double time = 0.0;                      ///< s of simulated time
  core::Vec3 force = core::Vec3::Zero();  ///< N, the tissue's force on the tool
  core::Vec3 axis = core::Vec3::UnitZ();  ///< the tool's shaft (the torque limit's axis)
  bool in_contact = false;                ///< the physics proxy touches the tissue
  /// m, the nodes the link's ContactSurface indexes (empty: no surface, the loop holds `force`).
  std::span<const core::Vec3> positions = {};
};

/// A device on the loopback interface. Alone (a headless live run) the owner's thread polls the
/// bridge and every physics step's force goes out at once, clamped to the device's limits.
/// Threaded (start_realtime … stop_realtime) a HapticDeviceLoop owns the bridge and answers the
/// device at ≥ 1 kHz from its local contact model over the latest published step.
class DeviceLink {
 public:
  /// Listens on `options` (port 0: any free port, see port()). Throws core::Error when the
  /// port cannot be bound.
  explicit DeviceLink(const BridgeOptions& options, const DeviceLimits& limits = {},
                      const DeviceLoopOptions& loop = {});
  ~DeviceLink();
  DeviceLink(const DeviceLink&) = delete;
  DeviceLink& operator=(const DeviceLink&) = delete;

  std::uint16_t port() const { return bridge_.port(); }
  const std::string& address() const { return address_; }

  /// The newest pose since the last call, if one arrived (non-blocking; every pending pose is
  /// read alone, the loop's newest taken threaded).
  std::optional<DevicePose> take_pose();
  /// After a physics step. Alone: sends `step.force` clamped to the device's limits (once a
  /// pose has told the bridge where the device is). Threaded: publishes the step to the loop.
  void feed_back(const DeviceStep& step);

  /// Starts the device loop: its local contact model walks on `surface` (empty: it holds each
  /// step's force) with a proxy spring of `stiffness` N/m, starting from `first`.
  void start_realtime(const ContactSurface& surface, double stiffness, const DeviceStep& first);
  /// Stops and joins the loop, keeping its counters; safe without a loop.
  void stop_realtime();

  /// The bridge's counters (alone; while threaded they belong to the loop's thread).
  const BridgeCounters& counters() const { return bridge_.counters(); }
  /// Feedback packets sent, alone and threaded.
  std::uint64_t feedback_sent() const;
  /// A device loop ran at a real-time priority.
  bool real_time() const;
  /// The device loop while threaded, else null.
  const HapticDeviceLoop* loop() const { return loop_.get(); }
  /// "udp ADDRESS:PORT (N poses, M forces sent[, waiting for the device])".
  std::string describe() const;

 private:
  UdpDeviceBridge bridge_;
  std::string address_;
  DeviceLimits limits_;
  DeviceLoopOptions loop_options_;
  std::uint32_t sequence_ = 0;
  std::uint64_t sent_ = 0;  ///< feedback sent alone
  ContactSurface surface_;  ///< of the loop's local contact model, while threaded
  std::unique_ptr<HapticDeviceLoop> loop_;
  std::uint64_t loop_sent_ = 0;  ///< feedback sent by loops that have stopped
  bool real_time_ = false;       ///< a stopped loop ran at a real-time priority
};

}  // namespace viscera::sim
