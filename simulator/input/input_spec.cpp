#include "simulator/input/input_spec.h"

#include <charconv>

#include "core/error.h"

namespace viscera::sim {

InputSpec parse_input_spec(const std::string& text) {
  const auto fail = [&](const std::string& why) -> InputSpec {
    throw core::UsageError("--input \"" + text + "\": " + why +
                           " (expected keyboard, gamepad, udp:PORT, trace:FILE or script:FILE)");
  };
  if (text == "keyboard") return {InputKind::Keyboard, 0, ""};
  if (text == "gamepad") return {InputKind::Gamepad, 0, ""};
  const auto colon = text.find(':');
  if (colon == std::string::npos) return fail("unknown input");
  const std::string kind = text.substr(0, colon);
  const std::string rest = text.substr(colon + 1);
  if (kind == "udp") {
    unsigned port = 0;
    const auto [end, error] = std::from_chars(rest.data(), rest.data() + rest.size(), port);
    if (rest.empty() || error != std::errc() || end != rest.data() + rest.size() || port > 65535)
      return fail("the port must be a number from 0 to 65535");
    return {InputKind::Udp, static_cast<std::uint16_t>(port), ""};
  }
  if (kind == "trace" || kind == "script") {
    if (rest.empty()) return fail("the file is missing");
    return {kind == "trace" ? InputKind::Trace : InputKind::Script, 0, rest};
  }
  return fail("unknown input");
}

}  // namespace viscera::sim
