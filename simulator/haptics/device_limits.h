#pragma once
/// Force and torque limits of the hysteroscopy haptic device (Spaelter et al. 2006; seed 000
/// §8.1): translational force 0.04–2 N, pitch and yaw torques up to 0.5 N·m, roll up to
/// 0.02 N·m. Commands beyond the limits are scaled down along their direction; translational
/// forces below 0.04 N cannot be rendered by the friction drive and are sent as zero.

#include "core/math_types.h"

namespace viscera::sim {

/// Limits of one device. Forces in N, torques in N·m.
struct DeviceLimits {
  double min_force = 0.04;
  double max_force = 2.0;
  double max_pitch_yaw_torque = 0.5;
  double max_roll_torque = 0.02;
};

/// Force and torque as the device can render them, and whether a limit cut in.
struct ClampedFeedback {
  core::Vec3 force = core::Vec3::Zero();   ///< N
  core::Vec3 torque = core::Vec3::Zero();  ///< N·m
  bool force_limited = false;
  bool torque_limited = false;
};

/// Clamps `force` and `torque` to `limits`; roll is the torque component along the unit
/// `tool_axis`, pitch and yaw the rest.
ClampedFeedback clamp_to_device(const core::Vec3& force, const core::Vec3& torque,
                                const core::Vec3& tool_axis, const DeviceLimits& limits = {});

}  // namespace viscera::sim
