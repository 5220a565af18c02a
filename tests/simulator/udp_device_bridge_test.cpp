#include "simulator/haptics/udp_device_bridge.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "simulator/haptics/simulated_device.h"

namespace viscera::sim {
namespace {

DevicePose pose(std::uint32_t sequence) {
  DevicePose p;
  p.sequence = sequence;
  p.time_ns = 1000000ULL * sequence;
  p.position = core::Vec3(0.01 * sequence, -0.02, 0.15);
  p.orientation = {0.9238795325112867, 0.0, 0.3826834323650898, 0.0};
  p.buttons = 0b101;
  p.inflow_valve = 0.75F;
  p.outflow_valve = 0.25F;
  return p;
}

TEST(DevicePackets, pose_and_feedback_round_trip_bit_exactly) {
  const DevicePose p = pose(42);
  EXPECT_EQ(decode_pose(encode_pose(p)), p);
  DeviceFeedback f;
  f.sequence = 7;
  f.force = core::Vec3(0.1, -1.9, 0.25);
  f.torque = core::Vec3(0.0, 0.3, 0.01);
  f.flags = kForceLimited;
  EXPECT_EQ(decode_feedback(encode_feedback(f)), f);
}

TEST(DevicePackets, damaged_packets_are_rejected) {
  auto bytes = encode_pose(pose(1));
  bytes[40] ^= 0x10;  // a flipped bit in the position
  EXPECT_FALSE(decode_pose(bytes).has_value());
  const auto good = encode_pose(pose(1));
  EXPECT_FALSE(
      decode_pose(std::span<const std::uint8_t>(good.data(), good.size() - 1)).has_value());
  EXPECT_FALSE(decode_feedback(good).has_value());  // a pose is not a feedback packet
  EXPECT_EQ(
      crc32(std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>("123456789"), 9)),
      0xCBF43926U);
}

TEST(UdpDeviceBridge, round_trips_on_loopback_dropping_malformed_and_late_packets) {
  UdpDeviceBridge bridge;  // 127.0.0.1, any free port
  ASSERT_GT(bridge.port(), 0);
  SimulatedDevice device(bridge.port());
  EXPECT_FALSE(bridge.send_feedback({}));  // no device heard yet
  ASSERT_TRUE(device.send(pose(1)));
  ASSERT_TRUE(device.send(pose(3)));
  ASSERT_TRUE(device.send(pose(2)));  // reordered: older than 3
  const std::uint8_t garbage[] = {1, 2, 3, 4, 5};
  ASSERT_TRUE(device.send_raw(garbage));
  ASSERT_TRUE(device.send(pose(4)));
  std::optional<DevicePose> newest;
  for (int attempt = 0;
       attempt < 50 &&
       bridge.counters().accepted + bridge.counters().late + bridge.counters().malformed < 5;
       ++attempt) {
    if (auto p = bridge.poll(20)) newest = p;
  }
  ASSERT_TRUE(newest.has_value());
  EXPECT_EQ(*newest, pose(4));
  EXPECT_EQ(bridge.counters().accepted, 3u);
  EXPECT_EQ(bridge.counters().late, 1u);
  EXPECT_EQ(bridge.counters().malformed, 1u);

  DeviceFeedback feedback;
  feedback.sequence = 4;
  feedback.force = core::Vec3(0.0, 0.0, 1.5);
  ASSERT_TRUE(bridge.send_feedback(feedback));
  const auto received = device.receive(1000);
  ASSERT_TRUE(received.has_value());
  EXPECT_EQ(*received, feedback);
}

TEST(UdpDeviceBridge, binds_to_loopback_by_default) {
  UdpDeviceBridge bridge;
  (void)bridge;
  UdpSocket probe;
  EXPECT_EQ(probe.local().address, parse_ipv4("127.0.0.1"));
  EXPECT_THROW(UdpSocket("not-an-address"), core::UsageError);
}

}  // namespace
}  // namespace viscera::sim
