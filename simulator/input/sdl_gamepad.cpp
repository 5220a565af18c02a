#include "simulator/input/sdl_gamepad.h"

#include <SDL.h>

#include <algorithm>

#include "core/error.h"

namespace viscera::sim {

SdlGamepad::SdlGamepad() {
  // The window is VTK's, not SDL's: read the pad whichever window has the focus.
  SDL_SetHint(SDL_HINT_JOYSTICK_ALLOW_BACKGROUND_EVENTS, "1");
  if (SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER) != 0)
    throw core::Error(std::string("SDL cannot start its game-controller support: ") +
                      SDL_GetError());
  SDL_GameControllerEventState(SDL_IGNORE);  // polled with SDL_GameControllerUpdate
  SDL_JoystickEventState(SDL_IGNORE);
  open_first();
}

SdlGamepad::~SdlGamepad() {
  if (pad_ != nullptr) SDL_GameControllerClose(pad_);
  SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
}

void SdlGamepad::open_first() {
  for (int i = 0; i < SDL_NumJoysticks(); ++i) {
    if (!SDL_IsGameController(i)) continue;
    pad_ = SDL_GameControllerOpen(i);
    if (pad_ != nullptr) return;
  }
}

std::string SdlGamepad::name() const {
  if (pad_ == nullptr) return {};
  const char* name = SDL_GameControllerName(pad_);
  return name != nullptr ? name : "unnamed game controller";
}

std::optional<GamepadState> SdlGamepad::read() {
  SDL_GameControllerUpdate();  // also detects pads plugged in or out
  if (pad_ != nullptr && !SDL_GameControllerGetAttached(pad_)) {
    SDL_GameControllerClose(pad_);
    pad_ = nullptr;
  }
  if (pad_ == nullptr) open_first();
  if (pad_ == nullptr) return std::nullopt;
  GamepadState state;
  for (int a = 0; a < static_cast<int>(GamepadAxis::Count); ++a) {
    const double raw = SDL_GameControllerGetAxis(pad_, static_cast<SDL_GameControllerAxis>(a));
    state.axes[static_cast<std::size_t>(a)] = std::clamp(raw / 32767.0, -1.0, 1.0);
  }
  for (int b = 0; b <= static_cast<int>(GamepadButton::DpadRight); ++b) {
    const bool down =
        SDL_GameControllerGetButton(pad_, static_cast<SDL_GameControllerButton>(b)) != 0;
    state.set(static_cast<GamepadButton>(b), down);
  }
  return state;
}

GamepadInput::GamepadInput(ManualControl& control, SdlGamepad& pad, double dead_zone,
                           double read_interval)
    : control_(control),
      pad_(pad),
      dead_zone_(dead_zone),
      read_interval_(read_interval),
      since_read_(read_interval) {}

InstrumentState GamepadInput::next(double dt) {
  since_read_ += dt;
  if (since_read_ >= read_interval_) {
    since_read_ = 0.0;
    const std::optional<GamepadState> now = pad_.read();
    const GamepadState reading = now.value_or(GamepadState{});
    const GamepadCommand command = map_gamepad(reading, previous_, dead_zone_);
    for (const ManualCommand pressed : command.pressed)
      control_.press(pressed);
    for (const ManualCommand released : command.released)
      control_.release(released);
    control_.set_analog(command.motion);
    previous_ = reading;
  }
  return control_.advance(dt);
}

std::string GamepadInput::describe() const {
  return pad_.connected() ? "gamepad \"" + pad_.name() + "\" and keyboard"
                          : "no gamepad found: keyboard and mouse";
}

}  // namespace viscera::sim
