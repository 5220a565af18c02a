#pragma once
/// The input source named on the command line (`viscera-sim run --input SPEC`, issue 8
/// item 9): "keyboard" (keyboard and mouse in the window), "gamepad" (a pad through SDL2, with
/// the keyboard), "udp:PORT" (a haptic device sending pose packets to 127.0.0.1:PORT; port 0
/// picks a free one), "trace:FILE" (a recorded session's trace replayed as the input) or
/// "script:FILE" (a viscera-script of timed waypoints).

#include <cstdint>
#include <string>

namespace viscera::sim {

enum class InputKind { Keyboard, Gamepad, Udp, Trace, Script };

struct InputSpec {
  InputKind kind = InputKind::Keyboard;
  std::uint16_t port = 0;  ///< for Udp
  std::string file;        ///< for Trace and Script
  bool operator==(const InputSpec&) const = default;
};

/// Parses `text`; throws core::UsageError naming the accepted forms for anything else.
InputSpec parse_input_spec(const std::string& text);

}  // namespace viscera::sim
