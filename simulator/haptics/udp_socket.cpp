#include "simulator/haptics/udp_socket.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <ctime>

#include "core/error.h"

namespace viscera::sim {
namespace {

sockaddr_in to_sockaddr(const UdpEndpoint& endpoint) {
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(endpoint.address);
  address.sin_port = htons(endpoint.port);
  return address;
}

}  // namespace

std::uint32_t parse_ipv4(const std::string& text) {
  in_addr parsed{};
  if (inet_pton(AF_INET, text.c_str(), &parsed) != 1)
    throw core::UsageError("\"" + text + "\" is not an IPv4 address");
  return ntohl(parsed.s_addr);
}

UdpSocket::UdpSocket(const std::string& address, std::uint16_t port) {
  const UdpEndpoint endpoint{parse_ipv4(address), port};
  fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd_ < 0) throw core::Error(std::string("cannot open a UDP socket: ") + std::strerror(errno));
  const sockaddr_in bind_address = to_sockaddr(endpoint);
  if (::bind(fd_, reinterpret_cast<const sockaddr*>(&bind_address), sizeof bind_address) != 0) {
    const std::string reason = std::strerror(errno);
    ::close(fd_);
    fd_ = -1;
    throw core::Error("cannot bind UDP " + address + ":" + std::to_string(port) + ": " + reason);
  }
}

UdpSocket::~UdpSocket() {
  if (fd_ >= 0) ::close(fd_);
}

UdpEndpoint UdpSocket::local() const {
  sockaddr_in address{};
  socklen_t length = sizeof address;
  ::getsockname(fd_, reinterpret_cast<sockaddr*>(&address), &length);
  return {ntohl(address.sin_addr.s_addr), ntohs(address.sin_port)};
}

bool UdpSocket::send_to(const UdpEndpoint& to, std::span<const std::uint8_t> bytes) {
  const sockaddr_in address = to_sockaddr(to);
  return ::sendto(fd_, bytes.data(), bytes.size(), 0, reinterpret_cast<const sockaddr*>(&address),
                  sizeof address) == static_cast<ssize_t>(bytes.size());
}

std::optional<std::size_t> UdpSocket::receive(std::vector<std::uint8_t>& buffer, UdpEndpoint& from,
                                              int timeout_ms) {
  if (timeout_ms > 0) {
    pollfd waiting{fd_, POLLIN, 0};
    if (::poll(&waiting, 1, timeout_ms) <= 0) return std::nullopt;
  }
  buffer.resize(2048);
  sockaddr_in address{};
  socklen_t length = sizeof address;
  const ssize_t got = ::recvfrom(fd_, buffer.data(), buffer.size(), 0,
                                 reinterpret_cast<sockaddr*>(&address), &length);
  if (got < 0) return std::nullopt;  // EAGAIN: nothing pending
  from = {ntohl(address.sin_addr.s_addr), ntohs(address.sin_port)};
  return static_cast<std::size_t>(got);
}

bool UdpSocket::wait_readable(std::chrono::microseconds timeout) const {
  pollfd waiting{fd_, POLLIN, 0};
  const long long us = std::max<long long>(0, timeout.count());
  const timespec span{static_cast<time_t>(us / 1000000), static_cast<long>((us % 1000000) * 1000)};
  return ::ppoll(&waiting, 1, &span, nullptr) > 0 && (waiting.revents & POLLIN) != 0;
}

}  // namespace viscera::sim
