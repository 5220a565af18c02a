#pragma once
/// Two hands in a laparoscopic session (issue 19 §3/§7): the working port (the right hand, with
/// the laparoscope) driven by any live input — a haptic device, the keyboard, a gamepad — and
/// the second instrument port (the left hand, InstrumentState::second) driven by a haptic
/// device of its own over UDP (`viscera-sim run … --left-device udp:PORT`).
///
/// A composite rather than a second kind of DeviceInput: the right hand's input is untouched
/// and stays whatever it was; this input asks it for the working port's state and overwrites
/// the second port with the left device's. The per-device machinery (bridge, device loop,
/// feedback sequence, counters) is one DeviceLink per device, the same class DeviceInput uses.
///
/// The left device owns the second port: empty until the device's first pose, then as its
/// poses say (second_port_from_pose: tool bits 4–6, kDeviceWithdrawn takes the tool out); the
/// keyboard's Tab and Backspace then move nothing in that port. Its abort button ends the
/// session like the right hand's. Its feedback is the tissue's force on the second port's tool
/// (SessionRunner::second_port_force, zero while the port is empty), clamped to the device's
/// limits: after every physics step alone, at ≥ 1 kHz from a second HapticDeviceLoop threaded.
/// That loop's local contact model walks on the world's only body when there is one; in a scene
/// of several bodies (the laparoscopy patient: uterus, tubes, ovaries, …) the second port's
/// proxy meets all of them and no single surface stands for it, so the loop holds each physics
/// step's force between steps. Its stiffness is the session's instrument stiffness, as the
/// second port's physics proxy.

#include <cstdint>
#include <memory>
#include <string>

#include "simulator/input/device_input.h"
#include "simulator/input/device_link.h"
#include "simulator/input/live_input.h"

namespace viscera::sim {

/// The right hand's live input with a left-hand device on the second port.
class TwoHandedInput final : public LiveInput {
 public:
  /// `right` drives the working port; the left hand's device listens on `left` (port 0: any
  /// free port, see left_port()). Throws core::Error when the port cannot be bound.
  TwoHandedInput(std::unique_ptr<LiveInput> right, const BridgeOptions& left,
                 const DeviceLimits& limits = {}, const DeviceLoopOptions& loop = {});
  ~TwoHandedInput() override;

  /// The right input's state with the second port from the left device's newest pose.
  InstrumentState next(double dt) override;
  const InstrumentState& current() const override { return state_; }
  /// The right input's after_step; then the second port's force to the left device.
  void after_step(const SessionRunner& runner) override;
  std::string describe() const override;
  /// Starts the right input's threads, then the left device's loop.
  void start_realtime(const SessionRunner& runner) override;
  void stop_realtime() override;
  /// The right input's counters, and the left device's as RealtimeStats::left_*.
  void add_stats(RealtimeStats& stats) const override;

  std::uint16_t left_port() const { return left_.port(); }
  const DeviceLink& left() const { return left_; }
  const LiveInput& right() const { return *right_; }

 private:
  std::unique_ptr<LiveInput> right_;
  DeviceLink left_;
  SecondPort second_;        ///< as the left device last set it
  bool left_abort_ = false;  ///< the left device's abort button is held
  InstrumentState state_;
};

}  // namespace viscera::sim
