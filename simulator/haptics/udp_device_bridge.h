#pragma once
/// The simulator's end of the haptic device link (seed 000 §8.2): pose packets in, force
/// packets out, over UDP bound to the loopback interface unless told otherwise. Malformed
/// packets and packets older than the newest accepted one (by sequence number) are dropped
/// and counted; the device's controller runs at ≥ 1 kHz and only the newest pose matters.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "simulator/haptics/device_packets.h"
#include "simulator/haptics/udp_socket.h"

namespace viscera::sim {

/// Where the bridge listens.
struct BridgeOptions {
  std::string bind_address =
      "127.0.0.1";         ///< loopback by default: no device on the network by accident
  std::uint16_t port = 0;  ///< 0 = any free port
};

/// Counts of what arrived.
struct BridgeCounters {
  std::uint64_t accepted = 0;
  std::uint64_t malformed = 0;  ///< wrong size, magic, version, kind, checksum or numbers
  std::uint64_t late = 0;       ///< sequence not newer than the last accepted pose
};

/// Receives device poses and sends force feedback.
class UdpDeviceBridge {
 public:
  explicit UdpDeviceBridge(const BridgeOptions& options = {});

  std::uint16_t port() const { return socket_.local().port; }

  /// Reads every pending datagram; returns the newest valid pose among them, if any arrived.
  /// Waits up to `timeout_ms` for the first datagram when positive.
  std::optional<DevicePose> poll(int timeout_ms = 0);
  /// Waits up to `timeout` for a datagram without reading it (the device loop's sub-millisecond
  /// wait between feedback packets); returns whether one is pending.
  bool wait(std::chrono::microseconds timeout) const { return socket_.wait_readable(timeout); }

  /// Sends feedback to the sender of the last accepted pose; false when none is known yet.
  bool send_feedback(const DeviceFeedback& feedback);

  const BridgeCounters& counters() const { return counters_; }

 private:
  UdpSocket socket_;
  BridgeCounters counters_;
  std::optional<std::uint32_t> last_sequence_;
  std::optional<UdpEndpoint> device_;
  std::vector<std::uint8_t> buffer_;
};

}  // namespace viscera::sim
