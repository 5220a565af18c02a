#include "simulator/input/device_link.h"

namespace viscera::sim {

DeviceLink::DeviceLink(const BridgeOptions& options, const DeviceLimits& limits,
                       const DeviceLoopOptions& loop)
    : bridge_(options), address_(options.bind_address), limits_(limits), loop_options_(loop) {
  loop_options_.limits = limits;
}

DeviceLink::~DeviceLink() {
  stop_realtime();
}

std::optional<DevicePose> DeviceLink::take_pose() {
  if (loop_ == nullptr) return bridge_.poll(0);
  DevicePose pose;
  if (loop_->newest_pose(pose)) return pose;
  return std::nullopt;
}

void DeviceLink::feed_back(const DeviceStep& step) {
  if (loop_ != nullptr) {
    TissueSnapshot& tissue = loop_->tissue_slot();
    tissue.steps = step.steps;
    tissue.force = step.force;
    tissue.in_contact = step.in_contact;
    if (!surface_.empty() && !step.positions.empty())
      surface_.gather(step.positions, tissue.surface);
    else
      tissue.surface.clear();
    loop_->publish_tissue();
    return;
  }
  const ClampedFeedback clamped =
      clamp_to_device(step.force, core::Vec3::Zero(), step.axis, limits_);
  DeviceFeedback feedback;
  feedback.sequence = ++sequence_;
  feedback.time_ns = static_cast<std::uint64_t>(step.time * 1e9);
  feedback.force = clamped.force;
  feedback.torque = clamped.torque;
  feedback.flags =
      (clamped.force_limited ? kForceLimited : 0U) | (clamped.torque_limited ? kTorqueLimited : 0U);
  if (bridge_.send_feedback(feedback)) ++sent_;
}

void DeviceLink::start_realtime(const ContactSurface& surface, double stiffness,
                                const DeviceStep& first) {
  if (loop_ != nullptr) return;
  surface_ = surface;
  loop_ = std::make_unique<HapticDeviceLoop>(bridge_, surface_, stiffness, loop_options_);
  // The loop's model starts from the state before the first step.
  feed_back(first);
  loop_->start();
}

void DeviceLink::stop_realtime() {
  if (loop_ == nullptr) return;
  loop_->stop();
  loop_sent_ += static_cast<std::uint64_t>(loop_->counters().feedback.load());
  real_time_ = real_time_ || loop_->counters().real_time_priority.load();
  loop_.reset();
}

std::uint64_t DeviceLink::feedback_sent() const {
  const std::uint64_t running =
      loop_ != nullptr ? static_cast<std::uint64_t>(loop_->counters().feedback.load()) : 0;
  return sent_ + loop_sent_ + running;
}

bool DeviceLink::real_time() const {
  return real_time_ || (loop_ != nullptr && loop_->counters().real_time_priority.load());
}

std::string DeviceLink::describe() const {
  const BridgeCounters& c = bridge_.counters();
  return "udp " + address_ + ":" + std::to_string(port()) + " (" + std::to_string(c.accepted) +
         " poses, " + std::to_string(feedback_sent()) + " forces sent" +
         (c.accepted == 0 ? ", waiting for the device" : "") + ")";
}

}  // namespace viscera::sim
