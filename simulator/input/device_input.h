#pragma once
/// A haptic device over UDP as a live input (issue 8 item 7; seed 000 §8.2): the instrument
/// follows the pose packets of UdpDeviceBridge and every physics step sends the tissue's force
/// back, clamped to the device's limits (DeviceLimits). The device reports in the scenario's
/// frame in metres: the position is the tip, the orientation quaternion turns the instrument's
/// rest frame (shaft along +z, optics' up along +y) into the scene.

#include <cstdint>
#include <string>

#include "simulator/haptics/device_limits.h"
#include "simulator/haptics/device_packets.h"
#include "simulator/haptics/udp_device_bridge.h"
#include "simulator/input/live_input.h"

namespace viscera::sim {

/// Bit of DevicePose::buttons that ends the session while held.
inline constexpr std::uint32_t kDeviceAbortButton = 1U;

/// The instrument state a pose describes: tip = position, axis = q·ẑ, up = q·ŷ (q normalised;
/// a zero quaternion counts as the identity), valves from the pose, abort from
/// kDeviceAbortButton.
InstrumentState instrument_from_pose(const DevicePose& pose);

/// The instrument driven by a device on the loopback interface.
class DeviceInput final : public LiveInput {
 public:
  /// Listens on `options` (port 0: any free port, see port()); until the first pose arrives
  /// the instrument rests at `start`. Throws core::Error when the port cannot be bound.
  DeviceInput(const BridgeOptions& options, const InstrumentState& start,
              const DeviceLimits& limits = {});

  std::uint16_t port() const { return bridge_.port(); }
  /// Reads every pending pose (non-blocking) and returns the newest one's state.
  InstrumentState next(double dt) override;
  const InstrumentState& current() const override { return state_; }
  /// Sends the tissue's force on the instrument, clamped to the device's limits.
  void after_step(const SessionRunner& runner) override;
  std::string describe() const override;

  const BridgeCounters& counters() const { return bridge_.counters(); }
  std::uint64_t feedback_sent() const { return sent_; }

 private:
  UdpDeviceBridge bridge_;
  std::string address_;
  DeviceLimits limits_;
  InstrumentState state_;
  std::uint32_t sequence_ = 0;
  std::uint64_t sent_ = 0;
};

}  // namespace viscera::sim
