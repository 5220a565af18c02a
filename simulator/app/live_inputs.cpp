#include "simulator/app/live_inputs.h"

#include "core/error.h"
#include "simulator/input/device_input.h"
#include "simulator/input/gamepad_mapping.h"
#include "simulator/input/two_handed_input.h"
#ifdef VISCERA_HAVE_SDL2
#include "simulator/input/sdl_gamepad.h"
#endif

namespace viscera::sim {
#ifndef VISCERA_HAVE_SDL2
class SdlGamepad {};  // a build without SDL2 never creates one
#endif
}  // namespace viscera::sim

namespace viscera::app {

LiveInputs::LiveInputs() = default;
LiveInputs::~LiveInputs() = default;
LiveInputs::LiveInputs(LiveInputs&&) noexcept = default;

LiveInputs open_live_input(const sim::InputSpec& spec, const sim::InstrumentState& start,
                           bool headless) {
  LiveInputs inputs;
  if (headless && spec.kind != sim::InputKind::Udp) {
    throw core::UsageError(
        "the keyboard and a gamepad drive the instrument from the window; a --headless run "
        "needs --script, --input trace:FILE or --input udp:PORT");
  }
  if (!headless) inputs.manual = std::make_unique<sim::ManualControl>(start);
  inputs.bindings = sim::ManualControl::bindings_text();
  switch (spec.kind) {
    case sim::InputKind::Udp: {
      auto device =
          std::make_unique<sim::DeviceInput>(sim::BridgeOptions{"127.0.0.1", spec.port}, start);
      inputs.status =
          "the haptic device drives the instrument: send pose packets to udp "
          "127.0.0.1:" +
          std::to_string(device->port());
      inputs.bindings = "Device on udp 127.0.0.1:" + std::to_string(device->port()) +
                        " (pose packets in, force packets out)   Esc or X: abort";
      inputs.live = std::move(device);
      break;
    }
    case sim::InputKind::Gamepad: {
#ifdef VISCERA_HAVE_SDL2
      inputs.pad = std::make_unique<sim::SdlGamepad>();
      auto gamepad = std::make_unique<sim::GamepadInput>(*inputs.manual, *inputs.pad);
      inputs.status = inputs.pad->connected()
                          ? "gamepad \"" + inputs.pad->name() +
                                "\" and the keyboard drive the "
                                "instrument"
                          : "no gamepad found: the keyboard and mouse drive the instrument (a "
                            "pad plugged in later is picked up)";
      inputs.bindings = (inputs.pad->connected() ? "Gamepad: " + inputs.pad->name()
                                                 : std::string("No gamepad found: keyboard")) +
                        "\n" + inputs.bindings + "\n" + sim::gamepad_bindings_text();
      inputs.live = std::move(gamepad);
#else
      inputs.status =
          "this build has no gamepad support (SDL2 was not found): the keyboard "
          "and mouse drive the instrument";
      inputs.live = std::make_unique<sim::KeyboardInput>(*inputs.manual);
#endif
      break;
    }
    default:
      inputs.status = "the keyboard and mouse drive the instrument";
      inputs.live = std::make_unique<sim::KeyboardInput>(*inputs.manual);
      break;
  }
  return inputs;
}

void add_left_device(LiveInputs& inputs, const sim::InputSpec& left) {
  auto two = std::make_unique<sim::TwoHandedInput>(std::move(inputs.live),
                                                   sim::BridgeOptions{"127.0.0.1", left.port});
  const std::string port = std::to_string(two->left_port());
  inputs.status +=
      "; the left hand's haptic device drives the second port: send pose packets to udp "
      "127.0.0.1:" +
      port;
  inputs.bindings += "\nLeft hand: device on udp 127.0.0.1:" + port +
                     " (second port; button bit 8 takes its tool out)";
  inputs.live = std::move(two);
}

}  // namespace viscera::app
