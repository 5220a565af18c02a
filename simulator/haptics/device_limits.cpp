#include "simulator/haptics/device_limits.h"

namespace viscera::sim {

ClampedFeedback clamp_to_device(const core::Vec3& force, const core::Vec3& torque,
                                const core::Vec3& tool_axis, const DeviceLimits& limits) {
  ClampedFeedback out;
  const double magnitude = force.norm();
  if (magnitude > limits.max_force) {
    out.force = force * (limits.max_force / magnitude);
    out.force_limited = true;
  } else if (magnitude >= limits.min_force) {
    out.force = force;
  }
  const core::Vec3 axis = tool_axis.normalized();
  core::Vec3 roll = axis * axis.dot(torque);
  core::Vec3 pitch_yaw = torque - roll;
  if (roll.norm() > limits.max_roll_torque) {
    roll *= limits.max_roll_torque / roll.norm();
    out.torque_limited = true;
  }
  if (pitch_yaw.norm() > limits.max_pitch_yaw_torque) {
    pitch_yaw *= limits.max_pitch_yaw_torque / pitch_yaw.norm();
    out.torque_limited = true;
  }
  out.torque = roll + pitch_yaw;
  return out;
}

}  // namespace viscera::sim
