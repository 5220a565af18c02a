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
#include "simulator/input/device_link.h"
#include "simulator/input/live_input.h"

namespace viscera::sim {

/// Bit of DevicePose::buttons that ends the session while held.
inline constexpr std::uint32_t kDeviceAbortButton = 1U;
/// Bits of DevicePose::buttons for the foot pedals: the loop's cutting and coagulating current.
inline constexpr std::uint32_t kDeviceCuttingPedal = 2U;
inline constexpr std::uint32_t kDeviceCoagulationPedal = 4U;
/// Bit of DevicePose::buttons for the laparoscopic tool's handle: set while the jaws are closed.
inline constexpr std::uint32_t kDeviceJawsClosed = 8U;
/// Bits 4–6 of DevicePose::buttons: the laparoscopic tool in the working port, as the index of
/// LaparoscopicTool (0 none, 1 grasper, 2 clip applier, 3 scissors, 4 bipolar, 5 suction, 6 hook;
/// 7 leaves the tool as it was). A second port's device (TwoHandedInput) names its tool the same
/// way.
inline constexpr int kDeviceToolShift = 4;
inline constexpr std::uint32_t kDeviceToolMask = 7U << kDeviceToolShift;
/// The tool bits that leave the tool as it was.
inline constexpr std::uint32_t kDeviceToolUnchanged = 7U;
/// Bit 7 of DevicePose::buttons: set while the suction–irrigation cannula's irrigation valve is
/// open (its suction valve is kDeviceJawsClosed).
inline constexpr std::uint32_t kDeviceIrrigating = 1U << 7;
/// Bit 8 of DevicePose::buttons, for a second port's device only: set while the left hand's tool
/// is out of the port. A pose without it puts the tool (bits 4–6) into the port at the pose, or
/// keeps it there; a pose with it takes the tool out (the rest of that pose is ignored). The
/// port stays as the last pose left it when the device falls silent. The working port's device
/// ignores the bit (its instrument is always in).
inline constexpr std::uint32_t kDeviceWithdrawn = 1U << 8;

/// The instrument state a pose describes: tip = position, axis = q·ẑ, up = q·ŷ (q normalised;
/// a zero quaternion counts as the identity), valves from the pose, abort, the pedals, the
/// laparoscopic tool, its jaws and the irrigation valve from the buttons. The loop stands at the
/// sheath (the device moves the whole instrument). Tool bits 7 keep `kept`, the tool the input
/// had.
InstrumentState instrument_from_pose(const DevicePose& pose,
                                     LaparoscopicTool kept = LaparoscopicTool::None);

/// The second port a pose of the left hand's device describes, from the port as it was
/// (`before`): with kDeviceWithdrawn an empty port; else the tool in, its tip, axis and up as
/// instrument_from_pose's, its jaws, pedals and irrigation valve from the same bits, its tool
/// from bits 4–6 (7: `before`'s tool).
SecondPort second_port_from_pose(const DevicePose& pose, const SecondPort& before);

/// The instrument driven by a device on the loopback interface. Alone (a headless live run)
/// it reads poses before and sends the step's force after every physics step, on the caller's
/// thread. In a threaded session (start_realtime) its I/O moves to a HapticDeviceLoop that
/// answers the device at ≥ 1 kHz from the local contact model; next() then takes the newest
/// pose that loop received and after_step() publishes the tissue's surface to it.
class DeviceInput final : public LiveInput {
 public:
  /// Listens on `options` (port 0: any free port, see port()); until the first pose arrives
  /// the instrument rests at `start`. Throws core::Error when the port cannot be bound.
  DeviceInput(const BridgeOptions& options, const InstrumentState& start,
              const DeviceLimits& limits = {}, const DeviceLoopOptions& loop = {});
  ~DeviceInput() override;

  std::uint16_t port() const { return link_.port(); }
  /// The newest pose's state (every pending pose is read; non-blocking).
  InstrumentState next(double dt) override;
  const InstrumentState& current() const override { return state_; }
  /// Alone: sends the tissue's force on the instrument, clamped to the device's limits.
  /// Threaded: publishes the tissue under the instrument to the device loop.
  void after_step(const SessionRunner& runner) override;
  std::string describe() const override;
  /// Starts the device loop with the surface and proxy stiffness of the runner's tissue.
  void start_realtime(const SessionRunner& runner) override;
  void stop_realtime() override;
  void add_stats(RealtimeStats& stats) const override;

  /// The bridge's counters (alone; while threaded they belong to the loop's thread).
  const BridgeCounters& counters() const { return link_.counters(); }
  /// Feedback packets sent, alone and threaded.
  std::uint64_t feedback_sent() const { return link_.feedback_sent(); }
  /// The device loop while threaded, else null.
  const HapticDeviceLoop* loop() const { return link_.loop(); }

 private:
  DeviceLink link_;
  InstrumentState state_;
};

}  // namespace viscera::sim
