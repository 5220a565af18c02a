#pragma once
/// A software stand-in for the haptic device: sends poses to a bridge over UDP and reads the
/// force feedback, so tests and benchmarks exercise the real socket path without hardware.

#include <optional>

#include "simulator/haptics/device_packets.h"
#include "simulator/haptics/udp_socket.h"

namespace viscera::sim {

/// A device endpoint on loopback.
class SimulatedDevice {
 public:
  /// Targets a bridge listening on 127.0.0.1:`bridge_port`.
  explicit SimulatedDevice(std::uint16_t bridge_port);

  /// Sends `pose` as is (sequence numbers are the caller's, so tests can reorder them).
  bool send(const DevicePose& pose);
  /// Sends raw bytes, for malformed-packet tests.
  bool send_raw(std::span<const std::uint8_t> bytes);
  /// The next feedback packet, waiting up to `timeout_ms`; nullopt on time-out or a bad packet.
  std::optional<DeviceFeedback> receive(int timeout_ms);

 private:
  UdpSocket socket_;
  UdpEndpoint bridge_;
  std::vector<std::uint8_t> buffer_;
};

}  // namespace viscera::sim
