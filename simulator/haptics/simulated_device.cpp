#include "simulator/haptics/simulated_device.h"

namespace viscera::sim {

SimulatedDevice::SimulatedDevice(std::uint16_t bridge_port)
    : socket_("127.0.0.1", 0), bridge_{parse_ipv4("127.0.0.1"), bridge_port} {}

bool SimulatedDevice::send(const DevicePose& pose) {
  const auto bytes = encode_pose(pose);
  return socket_.send_to(bridge_, bytes);
}

bool SimulatedDevice::send_raw(std::span<const std::uint8_t> bytes) {
  return socket_.send_to(bridge_, bytes);
}

std::optional<DeviceFeedback> SimulatedDevice::receive(int timeout_ms) {
  UdpEndpoint from;
  const auto size = socket_.receive(buffer_, from, timeout_ms);
  if (!size) return std::nullopt;
  return decode_feedback(std::span<const std::uint8_t>(buffer_.data(), *size));
}

}  // namespace viscera::sim
