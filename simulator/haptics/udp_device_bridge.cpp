#include "simulator/haptics/udp_device_bridge.h"

namespace viscera::sim {

UdpDeviceBridge::UdpDeviceBridge(const BridgeOptions& options)
    : socket_(options.bind_address, options.port) {}

std::optional<DevicePose> UdpDeviceBridge::poll(int timeout_ms) {
  std::optional<DevicePose> newest;
  UdpEndpoint from;
  int wait = timeout_ms;
  while (const auto size = socket_.receive(buffer_, from, wait)) {
    wait = 0;  // only the first read waits
    const auto pose = decode_pose(std::span<const std::uint8_t>(buffer_.data(), *size));
    if (!pose) {
      ++counters_.malformed;
      continue;
    }
    // Sequence numbers wrap after 2³² packets (50 days at 1 kHz): compare with wrap-around.
    if (last_sequence_ && static_cast<std::int32_t>(pose->sequence - *last_sequence_) <= 0) {
      ++counters_.late;
      continue;
    }
    last_sequence_ = pose->sequence;
    device_ = from;
    ++counters_.accepted;
    newest = pose;
  }
  return newest;
}

bool UdpDeviceBridge::send_feedback(const DeviceFeedback& feedback) {
  if (!device_) return false;
  const auto bytes = encode_feedback(feedback);
  return socket_.send_to(*device_, bytes);
}

}  // namespace viscera::sim
