#include "simulator/input/two_handed_input.h"

#include "simulator/session/session_report.h"
#include "simulator/session/session_runner.h"

namespace viscera::sim {

namespace {

/// The world's only body, or null when it holds several (or none).
const BodyView* only_body(const SessionRunner& runner) {
  const auto& bodies = runner.world().bodies();
  return bodies.size() == 1 ? &bodies.front() : nullptr;
}

/// The step the left hand's device feels: the second port's force, on the world's only body.
DeviceStep second_port_step(const SessionRunner& runner, const SecondPort& port) {
  DeviceStep step;
  step.steps = runner.world().steps();
  step.time = runner.world().time();
  step.force = runner.second_port_force();
  step.axis = port.axis;
  step.in_contact = step.force.squaredNorm() > 0.0;
  if (const BodyView* body = only_body(runner)) step.positions = body->positions();
  return step;
}

}  // namespace

TwoHandedInput::TwoHandedInput(std::unique_ptr<LiveInput> right, const BridgeOptions& left,
                               const DeviceLimits& limits, const DeviceLoopOptions& loop)
    : right_(std::move(right)), left_(left, limits, loop), state_(right_->current()) {
  state_.second = second_;
}

TwoHandedInput::~TwoHandedInput() {
  stop_realtime();
}

InstrumentState TwoHandedInput::next(double dt) {
  state_ = right_->next(dt);
  if (const auto pose = left_.take_pose()) {
    second_ = second_port_from_pose(*pose, second_);
    left_abort_ = (pose->buttons & kDeviceAbortButton) != 0U;
  }
  state_.second = second_;
  state_.abort = state_.abort || left_abort_;
  return state_;
}

void TwoHandedInput::after_step(const SessionRunner& runner) {
  right_->after_step(runner);
  left_.feed_back(second_port_step(runner, second_));
}

void TwoHandedInput::start_realtime(const SessionRunner& runner) {
  right_->start_realtime(runner);
  if (left_.loop() != nullptr) return;
  const BodyView* body = only_body(runner);
  left_.start_realtime(body != nullptr ? ContactSurface(body->surface_faces()) : ContactSurface(),
                       runner.instrument_stiffness(), second_port_step(runner, second_));
}

void TwoHandedInput::stop_realtime() {
  left_.stop_realtime();
  right_->stop_realtime();
}

void TwoHandedInput::add_stats(RealtimeStats& stats) const {
  right_->add_stats(stats);
  // Called once the session's threads have stopped, after stats.wall_time was set.
  stats.left_device = true;
  stats.left_device_poses = static_cast<long long>(left_.counters().accepted);
  stats.left_device_feedback = static_cast<long long>(left_.feedback_sent());
  stats.left_feedback_rate = stats.wall_time > 0.0
                                 ? static_cast<double>(stats.left_device_feedback) / stats.wall_time
                                 : 0.0;
  stats.left_device_real_time = left_.real_time();
}

std::string TwoHandedInput::describe() const {
  return right_->describe() + "; left hand: haptic device on " + left_.describe();
}

}  // namespace viscera::sim
