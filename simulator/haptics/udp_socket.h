#pragma once
/// A non-blocking IPv4 UDP socket (POSIX), owned RAII-style.

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace viscera::sim {

/// An IPv4 address and port.
struct UdpEndpoint {
  std::uint32_t address = 0;  ///< host byte order
  std::uint16_t port = 0;
  bool operator==(const UdpEndpoint&) const = default;
};

/// A bound UDP socket. Throws core::Error naming the address when it cannot be opened or bound.
class UdpSocket {
 public:
  /// Binds to `address` ("127.0.0.1" by default) and `port` (0 = any free port).
  explicit UdpSocket(const std::string& address = "127.0.0.1", std::uint16_t port = 0);
  ~UdpSocket();
  UdpSocket(const UdpSocket&) = delete;
  UdpSocket& operator=(const UdpSocket&) = delete;

  /// The bound endpoint (with the port the system chose for port 0).
  UdpEndpoint local() const;
  /// Sends one datagram; returns false if the system refused it.
  bool send_to(const UdpEndpoint& to, std::span<const std::uint8_t> bytes);
  /// Receives one pending datagram into `buffer` without blocking; nullopt when none is
  /// pending. Waits up to `timeout_ms` first when it is positive.
  std::optional<std::size_t> receive(std::vector<std::uint8_t>& buffer, UdpEndpoint& from,
                                     int timeout_ms = 0);
  /// Waits up to `timeout` (microsecond resolution, for loops at ≥ 1 kHz) until a datagram is
  /// pending; returns whether one is.
  bool wait_readable(std::chrono::microseconds timeout) const;

 private:
  int fd_ = -1;
};

/// "a.b.c.d" → host-order address; throws core::UsageError for anything else.
std::uint32_t parse_ipv4(const std::string& text);

}  // namespace viscera::sim
