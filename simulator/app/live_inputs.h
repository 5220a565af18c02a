#pragma once
/// The live input of `viscera-sim run --input …` (keyboard, gamepad, UDP device) with
/// everything it owns, and the bindings text the window shows for it.

#include <memory>
#include <string>

#include "simulator/input/input_spec.h"
#include "simulator/input/live_input.h"
#include "simulator/session/manual_control.h"

namespace viscera::sim {
class SdlGamepad;
}

namespace viscera::app {

/// A live input ready to run: `manual` takes the window's keys (null headless), `live` drives
/// the instrument, `status` says what drives it (printed and shown in the window).
struct LiveInputs {
  LiveInputs();
  ~LiveInputs();
  LiveInputs(LiveInputs&&) noexcept;
  std::unique_ptr<sim::ManualControl> manual;  ///< owned here: the inputs refer to it
  std::unique_ptr<sim::SdlGamepad> pad;
  std::unique_ptr<sim::LiveInput> live;
  std::string status;
  std::string bindings;  ///< the window's help text
};

/// Opens the source `spec` (Keyboard, Gamepad or Udp) with the instrument at `start`. Without a
/// window (`headless`) only Udp is possible (core::UsageError otherwise). A gamepad request
/// without a pad, or in a build without SDL2, falls back to the keyboard and says so in status.
LiveInputs open_live_input(const sim::InputSpec& spec, const sim::InstrumentState& start,
                           bool headless);

/// Adds a haptic device on 127.0.0.1:`left.port` (a Udp spec) for the second instrument port
/// (the left hand) to `inputs`, whose live input keeps the working port (TwoHandedInput); the
/// status names its bound port. Throws core::Error when the port cannot be bound.
void add_left_device(LiveInputs& inputs, const sim::InputSpec& left);

}  // namespace viscera::app
