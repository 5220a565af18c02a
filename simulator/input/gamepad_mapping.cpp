#include "simulator/input/gamepad_mapping.h"

#include <algorithm>
#include <cmath>

namespace viscera::sim {

void GamepadState::set(GamepadButton b, bool down) {
  const std::uint32_t bit = 1U << static_cast<int>(b);
  buttons = down ? (buttons | bit) : (buttons & ~bit);
}

double apply_dead_zone(double value, double dead_zone) {
  const double magnitude = std::min(1.0, std::abs(value));
  if (magnitude <= dead_zone) return 0.0;
  return std::copysign((magnitude - dead_zone) / (1.0 - dead_zone), value);
}

GamepadCommand map_gamepad(const GamepadState& now, const GamepadState& before, double dead_zone) {
  const auto axis = [&](GamepadAxis a) { return apply_dead_zone(now.axis(a), dead_zone); };
  const auto held = [&](GamepadButton b) { return now.pressed(b) ? 1.0 : 0.0; };
  GamepadCommand command;
  AnalogMotion& m = command.motion;
  m.advance = axis(GamepadAxis::TriggerRight) - axis(GamepadAxis::TriggerLeft) +
              held(GamepadButton::DpadUp) - held(GamepadButton::DpadDown);
  m.yaw = -axis(GamepadAxis::LeftX);    // stick right swings right
  m.pitch = -axis(GamepadAxis::LeftY);  // stick up (negative y) tilts up
  m.roll = -axis(GamepadAxis::RightX) + held(GamepadButton::LeftShoulder) -
           held(GamepadButton::RightShoulder);
  for (double* value : {&m.advance, &m.yaw, &m.pitch, &m.roll})
    *value = std::clamp(*value, -1.0, 1.0);

  const auto went_down = [&](GamepadButton b) { return now.pressed(b) && !before.pressed(b); };
  if (went_down(GamepadButton::A)) command.pressed.push_back(ManualCommand::ToggleInflow);
  if (went_down(GamepadButton::B)) command.pressed.push_back(ManualCommand::ToggleOutflow);
  if (went_down(GamepadButton::Back)) command.pressed.push_back(ManualCommand::Abort);
  if (went_down(GamepadButton::DpadRight)) command.pressed.push_back(ManualCommand::NextTool);
  if (went_down(GamepadButton::DpadLeft)) command.pressed.push_back(ManualCommand::PreviousTool);
  // Start switches hands (the second port's tool), Guide takes the second port's tool out.
  if (went_down(GamepadButton::Start)) command.pressed.push_back(ManualCommand::SwitchHand);
  if (went_down(GamepadButton::Guide)) command.pressed.push_back(ManualCommand::WithdrawSecondTool);
  // Held buttons: X the cutting pedal, Y the coagulation pedal, the right stick's click the
  // laparoscopic tool's jaws (the suction valve), the left stick's click the irrigation valve.
  const auto hold = [&](GamepadButton b, ManualCommand c) {
    if (went_down(b)) command.pressed.push_back(c);
    if (!now.pressed(b) && before.pressed(b)) command.released.push_back(c);
  };
  hold(GamepadButton::X, ManualCommand::CuttingPedal);
  hold(GamepadButton::Y, ManualCommand::CoagulationPedal);
  hold(GamepadButton::RightStick, ManualCommand::CloseJaws);
  hold(GamepadButton::LeftStick, ManualCommand::Irrigate);
  return command;
}

std::string gamepad_bindings_text() {
  return "Pad: left stick swing/tilt   RT/LT or d-pad: advance/withdraw   right stick or "
         "LB/RB: roll the optics\n"
         "Pad: A/B inflow/outflow valve   X cutting pedal   Y coagulation pedal   right stick "
         "click: jaws/suction   left stick click: irrigation   d-pad left/right: tool   Back: "
         "abort\n"
         "Pad: Start switch hands (the left hand's tool in the second port)   Guide: take it out";
}

}  // namespace viscera::sim
