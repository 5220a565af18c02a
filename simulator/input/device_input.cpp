#include "simulator/input/device_input.h"

#include <Eigen/Geometry>

#include "simulator/session/session_report.h"
#include "simulator/session/session_runner.h"

namespace viscera::sim {

InstrumentState instrument_from_pose(const DevicePose& pose, LaparoscopicTool kept) {
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
  state.tool = tool <= static_cast<std::uint32_t>(kLastLaparoscopicTool)
                   ? static_cast<LaparoscopicTool>(tool)
                   : kept;
  orthonormalise(state);
  return state;
}

SecondPort second_port_from_pose(const DevicePose& pose, const SecondPort& before) {
  if ((pose.buttons & kDeviceWithdrawn) != 0U) return SecondPort{};
  return port_tool(instrument_from_pose(pose, before.tool));
}

DeviceInput::DeviceInput(const BridgeOptions& options, const InstrumentState& start,
                         const DeviceLimits& limits, const DeviceLoopOptions& loop)
    : link_(options, limits, loop), state_(start) {}

DeviceInput::~DeviceInput() {
  stop_realtime();
}

InstrumentState DeviceInput::next(double) {
  if (const auto pose = link_.take_pose()) state_ = instrument_from_pose(*pose, state_.tool);
  return state_;
}

namespace {

/// The step the working port's device feels: the instrument's force and the tissue's body.
DeviceStep working_port_step(const SessionRunner& runner, const InstrumentState& state) {
  DeviceStep step;
  step.steps = runner.world().steps();
  step.time = runner.world().time();
  step.force = runner.instrument_force();
  step.axis = state.axis;
  step.in_contact = runner.tissue() != nullptr && runner.tissue()->in_contact();
  const BodyView* body = runner.tissue() != nullptr ? runner.tissue()->body() : nullptr;
  if (body != nullptr) step.positions = body->positions();
  return step;
}

}  // namespace

void DeviceInput::after_step(const SessionRunner& runner) {
  link_.feed_back(working_port_step(runner, state_));
}

void DeviceInput::start_realtime(const SessionRunner& runner) {
  if (link_.loop() != nullptr) return;
  const BodyView* body = runner.tissue() != nullptr ? runner.tissue()->body() : nullptr;
  link_.start_realtime(body != nullptr ? ContactSurface(body->surface_faces()) : ContactSurface(),
                       runner.instrument_stiffness(), working_port_step(runner, state_));
}

void DeviceInput::stop_realtime() {
  link_.stop_realtime();
}

void DeviceInput::add_stats(RealtimeStats& stats) const {
  // Called once the session's threads have stopped, so the bridge's counters are settled.
  stats.device = true;
  stats.device_poses = static_cast<long long>(link_.counters().accepted);
  stats.device_feedback = static_cast<long long>(link_.feedback_sent());
  stats.device_real_time = link_.real_time();
}

std::string DeviceInput::describe() const {
  return "haptic device on " + link_.describe();
}

}  // namespace viscera::sim
