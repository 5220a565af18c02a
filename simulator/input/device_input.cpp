#include "simulator/input/device_input.h"

#include <Eigen/Geometry>

#include "simulator/session/session_report.h"
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
  state.electrode = (pose.buttons & kDeviceCuttingPedal) != 0U;
  state.coagulation = (pose.buttons & kDeviceCoagulationPedal) != 0U;
  state.jaws_closed = (pose.buttons & kDeviceJawsClosed) != 0U;
  state.irrigating = (pose.buttons & kDeviceIrrigating) != 0U;
  const std::uint32_t tool = (pose.buttons & kDeviceToolMask) >> kDeviceToolShift;
  if (tool <= static_cast<std::uint32_t>(kLastLaparoscopicTool))
    state.tool = static_cast<LaparoscopicTool>(tool);
  orthonormalise(state);
  return state;
}

DeviceInput::DeviceInput(const BridgeOptions& options, const InstrumentState& start,
                         const DeviceLimits& limits, const DeviceLoopOptions& loop)
    : bridge_(options),
      address_(options.bind_address),
      limits_(limits),
      loop_options_(loop),
      state_(start) {
  loop_options_.limits = limits;
}

DeviceInput::~DeviceInput() {
  stop_realtime();
}

InstrumentState DeviceInput::next(double) {
  if (loop_ != nullptr) {
    DevicePose pose;
    if (loop_->newest_pose(pose)) state_ = instrument_from_pose(pose);
  } else if (const auto pose = bridge_.poll(0)) {
    state_ = instrument_from_pose(*pose);
  }
  return state_;
}

void DeviceInput::after_step(const SessionRunner& runner) {
  if (loop_ != nullptr) {
    TissueSnapshot& tissue = loop_->tissue_slot();
    tissue.steps = runner.world().steps();
    tissue.force = runner.instrument_force();
    tissue.in_contact = runner.tissue() != nullptr && runner.tissue()->in_contact();
    const BodyView* body = runner.tissue() != nullptr ? runner.tissue()->body() : nullptr;
    if (body != nullptr && !surface_.empty())
      surface_.gather(body->positions(), tissue.surface);
    else
      tissue.surface.clear();
    loop_->publish_tissue();
    return;
  }
  const ClampedFeedback clamped =
      clamp_to_device(runner.instrument_force(), core::Vec3::Zero(), state_.axis, limits_);
  DeviceFeedback feedback;
  feedback.sequence = ++sequence_;
  feedback.time_ns = static_cast<std::uint64_t>(runner.world().time() * 1e9);
  feedback.force = clamped.force;
  feedback.torque = clamped.torque;
  feedback.flags =
      (clamped.force_limited ? kForceLimited : 0U) | (clamped.torque_limited ? kTorqueLimited : 0U);
  if (bridge_.send_feedback(feedback)) ++sent_;
}

void DeviceInput::start_realtime(const SessionRunner& runner) {
  if (loop_ != nullptr) return;
  const BodyView* body = runner.tissue() != nullptr ? runner.tissue()->body() : nullptr;
  surface_ = body != nullptr ? ContactSurface(body->surface_faces()) : ContactSurface();
  loop_ = std::make_unique<HapticDeviceLoop>(bridge_, surface_, runner.instrument_stiffness(),
                                             loop_options_);
  // The loop's model starts from the state before the first step.
  after_step(runner);
  loop_->start();
}

void DeviceInput::stop_realtime() {
  if (loop_ == nullptr) return;
  loop_->stop();
  loop_sent_ += static_cast<std::uint64_t>(loop_->counters().feedback.load());
  real_time_ = real_time_ || loop_->counters().real_time_priority.load();
  loop_.reset();
}

std::uint64_t DeviceInput::feedback_sent() const {
  const std::uint64_t running =
      loop_ != nullptr ? static_cast<std::uint64_t>(loop_->counters().feedback.load()) : 0;
  return sent_ + loop_sent_ + running;
}

void DeviceInput::add_stats(RealtimeStats& stats) const {
  // Called once the session's threads have stopped, so the bridge's counters are settled.
  stats.device = true;
  stats.device_poses = static_cast<long long>(bridge_.counters().accepted);
  stats.device_feedback = static_cast<long long>(feedback_sent());
  stats.device_real_time = real_time_;
}

std::string DeviceInput::describe() const {
  const BridgeCounters& c = bridge_.counters();
  return "haptic device on udp " + address_ + ":" + std::to_string(port()) + " (" +
         std::to_string(c.accepted) + " poses, " + std::to_string(feedback_sent()) +
         " forces sent" + (c.accepted == 0 ? ", waiting for the device" : "") + ")";
}

}  // namespace viscera::sim
