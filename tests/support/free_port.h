#pragma once
// A UDP port on loopback that was free a moment ago, for tests that start a program listening on
// it (header-only: the tests that use it link the simulator's UDP socket).

#include <cstdint>

#include "simulator/haptics/udp_socket.h"

namespace viscera::testing {

/// Binds port 0 on 127.0.0.1, reads the port the system chose, and releases it.
inline std::uint16_t free_port() {
  const sim::UdpSocket probe("127.0.0.1", 0);
  return probe.local().port;
}

}  // namespace viscera::testing
