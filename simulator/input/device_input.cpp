#include "simulator/input/device_input.h"

#include <Eigen/Geometry>

#include "simulator/session/session_runner.h"

namespace viscera::sim {

InstrumentState instrument_from_pose(const DevicePose& pose) {
  const auto& o = pose.orientation;
  Eigen::Quaterniond q(o[0], o[1], o[2], o[3]);
  if (q.norm() < 1e-12) q = Eigen::Quaterniond::Identity();
  q.normalize();
  InstrumentState state;
  state.tip = pose.position;
  state.axis = q * core::Vec3(core::Vec3::UnitZ());
  state.up = q * core::Vec3(core::Vec3::UnitY());
  state.inflow = static_cast<double>(pose.inflow_valve);
  state.outflow = static_cast<double>(pose.outflow_valve);
  state.abort = (pose.buttons & kDeviceAbortButton) != 0U;
  orthonormalise(state);
  return state;
}

DeviceInput::DeviceInput(const BridgeOptions& options, const InstrumentState& start,
                         const DeviceLimits& limits)
    : bridge_(options), address_(options.bind_address), limits_(limits), state_(start) {}

InstrumentState DeviceInput::next(double) {
  if (const auto pose = bridge_.poll(0)) state_ = instrument_from_pose(*pose);
  return state_;
}

void DeviceInput::after_step(const SessionRunner& runner) {
  const ClampedFeedback clamped =
      clamp_to_device(runner.world().instrument_force(), core::Vec3::Zero(), state_.axis, limits_);
  DeviceFeedback feedback;
  feedback.sequence = ++sequence_;
  feedback.time_ns = static_cast<std::uint64_t>(runner.world().time() * 1e9);
  feedback.force = clamped.force;
  feedback.torque = clamped.torque;
  feedback.flags =
      (clamped.force_limited ? kForceLimited : 0U) | (clamped.torque_limited ? kTorqueLimited : 0U);
  if (bridge_.send_feedback(feedback)) ++sent_;
}

std::string DeviceInput::describe() const {
  const BridgeCounters& c = bridge_.counters();
  return "haptic device on udp " + address_ + ":" + std::to_string(port()) + " (" +
         std::to_string(c.accepted) + " poses, " + std::to_string(sent_) + " forces sent" +
         (c.accepted == 0 ? ", waiting for the device" : "") + ")";
}

}  // namespace viscera::sim
