// Gamepad state to instrument commands: dead zone, directions, edges of the valve buttons.

#include "simulator/input/gamepad_mapping.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "simulator/input/input_spec.h"

namespace viscera::sim {
namespace {

TEST(GamepadMapping, dead_zone_removes_drift_and_keeps_the_full_range) {
  EXPECT_EQ(apply_dead_zone(0.1, 0.15), 0.0);
  EXPECT_EQ(apply_dead_zone(-0.15, 0.15), 0.0);
  EXPECT_DOUBLE_EQ(apply_dead_zone(1.0, 0.15), 1.0);
  EXPECT_DOUBLE_EQ(apply_dead_zone(-1.0, 0.15), -1.0);
  EXPECT_NEAR(apply_dead_zone(0.575, 0.15), 0.5, 1e-12);  // halfway between the edge and full
  EXPECT_NEAR(apply_dead_zone(-0.575, 0.15), -0.5, 1e-12);
  EXPECT_DOUBLE_EQ(apply_dead_zone(1.3, 0.15), 1.0) << "over-range readings are clamped";
}

TEST(GamepadMapping, sticks_and_triggers_map_to_motions_with_their_signs) {
  GamepadState pad;
  pad.axes[static_cast<int>(GamepadAxis::LeftX)] = 1.0;   // stick right
  pad.axes[static_cast<int>(GamepadAxis::LeftY)] = -1.0;  // stick up (SDL's y points down)
  pad.axes[static_cast<int>(GamepadAxis::TriggerRight)] = 0.575;
  pad.axes[static_cast<int>(GamepadAxis::RightX)] = 0.05;  // resting drift
  const GamepadCommand command = map_gamepad(pad, pad);
  EXPECT_DOUBLE_EQ(command.motion.yaw, -1.0) << "stick right swings right (negative yaw)";
  EXPECT_DOUBLE_EQ(command.motion.pitch, 1.0) << "stick up tilts up";
  EXPECT_NEAR(command.motion.advance, 0.5, 1e-12);
  EXPECT_EQ(command.motion.roll, 0.0) << "drift inside the dead zone does not roll";
  EXPECT_TRUE(command.pressed.empty()) << "no button went down";

  GamepadState back;
  back.axes[static_cast<int>(GamepadAxis::TriggerLeft)] = 1.0;
  back.axes[static_cast<int>(GamepadAxis::TriggerRight)] = 0.0;
  back.set(GamepadButton::RightShoulder, true);
  back.set(GamepadButton::DpadDown, true);
  const GamepadCommand withdraw = map_gamepad(back, back);
  EXPECT_DOUBLE_EQ(withdraw.motion.advance, -1.0) << "trigger and d-pad clamp at full rate";
  EXPECT_DOUBLE_EQ(withdraw.motion.roll, -1.0) << "right shoulder rolls right";
}

TEST(GamepadMapping, valve_and_abort_buttons_act_once_per_press) {
  GamepadState up, down;
  down.set(GamepadButton::A, true);
  down.set(GamepadButton::B, true);
  const GamepadCommand first = map_gamepad(down, up);
  ASSERT_EQ(first.pressed.size(), 2u);
  EXPECT_EQ(first.pressed[0], ManualCommand::ToggleInflow);
  EXPECT_EQ(first.pressed[1], ManualCommand::ToggleOutflow);
  EXPECT_TRUE(map_gamepad(down, down).pressed.empty()) << "a held button does not repeat";
  GamepadState back = up;
  back.set(GamepadButton::Back, true);
  EXPECT_EQ(map_gamepad(back, up).pressed, std::vector<ManualCommand>{ManualCommand::Abort});
  // The left stick's click holds the irrigation valve open while it is held.
  GamepadState click = up;
  click.set(GamepadButton::LeftStick, true);
  EXPECT_EQ(map_gamepad(click, up).pressed, std::vector<ManualCommand>{ManualCommand::Irrigate});
  EXPECT_TRUE(map_gamepad(click, click).pressed.empty());
  EXPECT_EQ(map_gamepad(up, click).released, std::vector<ManualCommand>{ManualCommand::Irrigate});
}

TEST(GamepadMapping, drives_the_manual_control_proportionally) {
  InstrumentState start;
  start.axis = core::Vec3::UnitX();
  start.up = core::Vec3::UnitZ();
  ManualRates rates;
  rates.advance = 0.02;
  ManualControl control(start, rates);
  GamepadState pad;
  pad.axes[static_cast<int>(GamepadAxis::TriggerRight)] = 0.575;  // half rate
  const GamepadCommand command = map_gamepad(pad, GamepadState{});
  control.set_analog(command.motion);
  for (int i = 0; i < 1000; ++i)
    control.advance(1e-3);  // 1 s
  EXPECT_NEAR(control.state().tip.x(), 0.01, 1e-12);
  control.press(ManualCommand::Advance);  // key and pad add up, clamped to the full rate
  control.advance(0.5);
  EXPECT_NEAR(control.state().tip.x(), 0.02, 1e-12);
}

TEST(InputSpec, parses_every_source_and_refuses_the_rest) {
  EXPECT_EQ(parse_input_spec("keyboard").kind, InputKind::Keyboard);
  EXPECT_EQ(parse_input_spec("gamepad").kind, InputKind::Gamepad);
  EXPECT_EQ(parse_input_spec("udp:7000"), (InputSpec{InputKind::Udp, 7000, ""}));
  EXPECT_EQ(parse_input_spec("udp:0").port, 0);
  EXPECT_EQ(parse_input_spec("trace:a/b.json"), (InputSpec{InputKind::Trace, 0, "a/b.json"}));
  EXPECT_EQ(parse_input_spec("script:s.json").kind, InputKind::Script);
  for (const char* bad : {"mouse", "udp:", "udp:70000", "udp:12x", "trace:", "joystick:1"})
    EXPECT_THROW(parse_input_spec(bad), core::UsageError) << bad;
}

}  // namespace
}  // namespace viscera::sim
