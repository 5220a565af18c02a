#pragma once
/// The binary packets of the haptic device bridge, version 1 (seed 000 §8.2: displacement and
/// force data exchanged over UDP with the device's low-level controller). All fields are
/// little-endian; each packet ends with a CRC-32 of the bytes before it.
///
// clang-format off
/// | packet   | bytes | fields                                                                |
/// |----------|-------|-----------------------------------------------------------------------|
/// | pose     | 96    | magic "VSCD", version u16, kind u16 = 1, sequence u32, reserved u32, time ns u64, position 3×f64 (m), orientation quaternion w,x,y,z 4×f64, buttons u32, inflow valve f32, outflow valve f32 (0–1), crc32 |
/// | feedback | 80    | magic "VSCD", version u16, kind u16 = 2, sequence u32, reserved u32, time ns u64, force 3×f64 (N), torque 3×f64 (N·m), flags u32, crc32 |
// clang-format on

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "core/math_types.h"

namespace viscera::sim {

inline constexpr std::uint16_t kDevicePacketVersion = 1;
inline constexpr std::size_t kPosePacketBytes = 96;
inline constexpr std::size_t kFeedbackPacketBytes = 80;

/// What the device reports: the instrument's pose, buttons and valve openings.
struct DevicePose {
  std::uint32_t sequence = 0;
  std::uint64_t time_ns = 0;
  core::Vec3 position = core::Vec3::Zero();       ///< m
  std::array<double, 4> orientation{1, 0, 0, 0};  ///< unit quaternion w, x, y, z
  std::uint32_t buttons = 0;
  float inflow_valve = 0.0F;  ///< 0 closed … 1 open
  float outflow_valve = 0.0F;

  bool operator==(const DevicePose&) const = default;
};

/// Flags of a feedback packet.
enum FeedbackFlags : std::uint32_t { kForceLimited = 1U, kTorqueLimited = 2U, kWarning = 4U };

/// What the simulator sends back: force and torque to render.
struct DeviceFeedback {
  std::uint32_t sequence = 0;
  std::uint64_t time_ns = 0;
  core::Vec3 force = core::Vec3::Zero();   ///< N
  core::Vec3 torque = core::Vec3::Zero();  ///< N·m
  std::uint32_t flags = 0;

  bool operator==(const DeviceFeedback&) const = default;
};

std::array<std::uint8_t, kPosePacketBytes> encode_pose(const DevicePose& pose);
std::array<std::uint8_t, kFeedbackPacketBytes> encode_feedback(const DeviceFeedback& feedback);

/// Decodes a pose; nullopt for a wrong size, magic, version, kind, checksum or non-finite
/// numbers (such packets are dropped and counted, never trusted).
std::optional<DevicePose> decode_pose(std::span<const std::uint8_t> bytes);
std::optional<DeviceFeedback> decode_feedback(std::span<const std::uint8_t> bytes);

/// CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320) of `bytes`.
std::uint32_t crc32(std::span<const std::uint8_t> bytes);

}  // namespace viscera::sim
