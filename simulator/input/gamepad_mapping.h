#pragma once
/// Gamepad axes and buttons as instrument commands (issue 8 item 1; seed 002 §6: the trainee
/// may drive the instrument from a game controller instead of the keyboard). The layout is
/// SDL2's game-controller layout (an Xbox-style pad), so any pad SDL knows maps the same way.
/// The mapping is a pure function of the pad's state, tested without hardware.
///
/// | control                 | instrument command                                 |
/// |-------------------------|----------------------------------------------------|
/// | left stick left/right   | swing (rotate) the shaft left/right                |
/// | left stick up/down      | tilt the shaft up/down                             |
/// | right trigger / left    | advance / withdraw (proportional)                  |
/// | d-pad up / down         | advance / withdraw (full rate)                     |
/// | right stick left/right  | roll the optics left/right (proportional)          |
/// | left / right shoulder   | roll the optics left/right (full rate)             |
/// | A / B                   | inflow / outflow valve open ↔ closed               |
/// | Back                    | end the session (abort)                            |

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "simulator/session/manual_control.h"

namespace viscera::sim {

/// Axes in SDL_GameControllerAxis order.
enum class GamepadAxis { LeftX, LeftY, RightX, RightY, TriggerLeft, TriggerRight, Count };
/// Buttons in SDL_GameControllerButton order (bit i of GamepadState::buttons).
enum class GamepadButton {
  A,
  B,
  X,
  Y,
  Back,
  Guide,
  Start,
  LeftStick,
  RightStick,
  LeftShoulder,
  RightShoulder,
  DpadUp,
  DpadDown,
  DpadLeft,
  DpadRight
};

/// One reading of a pad. Sticks in [−1, 1] (x right, y down, as SDL reports them), triggers in
/// [0, 1].
struct GamepadState {
  std::array<double, static_cast<int>(GamepadAxis::Count)> axes{};
  std::uint32_t buttons = 0;

  double axis(GamepadAxis a) const { return axes[static_cast<int>(a)]; }
  bool pressed(GamepadButton b) const { return (buttons >> static_cast<int>(b)) & 1U; }
  void set(GamepadButton b, bool down);
  bool operator==(const GamepadState&) const = default;
};

/// What one reading asks of the instrument: the proportional motion, and the toggles and abort
/// of the buttons that went down since the previous reading (each press acts once).
struct GamepadCommand {
  AnalogMotion motion;
  std::vector<ManualCommand> pressed;
  std::vector<ManualCommand> released;  ///< held commands whose button came up
};

/// A stick or trigger deflection with the dead zone removed: 0 for |value| ≤ dead_zone, then
/// rising linearly to ±1 at full deflection (so small drift never moves the tool and the full
/// range stays reachable). `dead_zone` in [0, 1).
double apply_dead_zone(double value, double dead_zone);

/// The command of reading `now` after reading `before` (dead zone as a fraction of full
/// deflection, default 0.15: pads rest within about 10 % of centre).
GamepadCommand map_gamepad(const GamepadState& now, const GamepadState& before,
                           double dead_zone = 0.15);

/// The gamepad bindings as the window shows them.
std::string gamepad_bindings_text();

}  // namespace viscera::sim
