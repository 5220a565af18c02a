// The real SDL2 path with a virtual game controller (SDL_JoystickAttachVirtualEx, SDL ≥ 2.24):
// SDL's own mapping, scaling and polling feed the same ManualControl as the keyboard.

#ifdef VISCERA_HAVE_SDL2

#include "simulator/input/sdl_gamepad.h"

#include <SDL.h>
#include <gtest/gtest.h>

namespace viscera::sim {
namespace {

/// A virtual pad with every standard axis and button, attached for the test's lifetime.
class VirtualPad {
 public:
  VirtualPad() {
    SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER);
    SDL_VirtualJoystickDesc desc{};
    desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
    desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
    desc.naxes = SDL_CONTROLLER_AXIS_MAX;
    desc.nbuttons = SDL_CONTROLLER_BUTTON_DPAD_RIGHT + 1;
    desc.axis_mask = (1U << SDL_CONTROLLER_AXIS_MAX) - 1U;
    desc.button_mask = (1U << (SDL_CONTROLLER_BUTTON_DPAD_RIGHT + 1)) - 1U;
    desc.name = "Viscera test pad";
    index_ = SDL_JoystickAttachVirtualEx(&desc);
    if (index_ >= 0) joystick_ = SDL_JoystickOpen(index_);
  }
  ~VirtualPad() {
    if (joystick_ != nullptr) SDL_JoystickClose(joystick_);
    if (index_ >= 0) SDL_JoystickDetachVirtual(index_);
    SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
  }
  bool attached() const { return joystick_ != nullptr; }
  void axis(SDL_GameControllerAxis a, Sint16 value) {
    SDL_JoystickSetVirtualAxis(joystick_, a, value);
  }
  void button(SDL_GameControllerButton b, bool down) {
    SDL_JoystickSetVirtualButton(joystick_, b, down ? 1 : 0);
  }

 private:
  int index_ = -1;
  SDL_Joystick* joystick_ = nullptr;
};

TEST(SdlGamepad, a_virtual_pad_is_read_through_sdl_and_drives_the_instrument) {
  VirtualPad virtual_pad;
  ASSERT_TRUE(virtual_pad.attached()) << SDL_GetError();
  SdlGamepad pad;
  ASSERT_TRUE(pad.connected());
  EXPECT_EQ(pad.name(), "Viscera test pad");

  // SDL maps a virtual pad's full axis range onto a trigger's 0 … 1: −32768 is released.
  virtual_pad.axis(SDL_CONTROLLER_AXIS_TRIGGERLEFT, -32768);
  virtual_pad.axis(SDL_CONTROLLER_AXIS_LEFTX, 32767);  // full right
  virtual_pad.axis(SDL_CONTROLLER_AXIS_LEFTY, 0);
  virtual_pad.axis(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 32767);
  virtual_pad.button(SDL_CONTROLLER_BUTTON_A, true);
  const std::optional<GamepadState> state = pad.read();
  ASSERT_TRUE(state.has_value());
  EXPECT_DOUBLE_EQ(state->axis(GamepadAxis::LeftX), 1.0);
  EXPECT_DOUBLE_EQ(state->axis(GamepadAxis::LeftY), 0.0);
  EXPECT_DOUBLE_EQ(state->axis(GamepadAxis::TriggerRight), 1.0);
  EXPECT_DOUBLE_EQ(state->axis(GamepadAxis::TriggerLeft), 0.0);
  EXPECT_TRUE(state->pressed(GamepadButton::A));
  EXPECT_FALSE(state->pressed(GamepadButton::B));

  InstrumentState start;
  start.axis = core::Vec3::UnitX();
  start.up = core::Vec3::UnitZ();
  ManualRates rates;
  rates.advance = 0.02;
  rates.swing = 0.0;  // only the advance is checked for its length here
  ManualControl control(start, rates);
  GamepadInput input(control, pad);
  for (int i = 0; i < 500; ++i)
    input.next(1e-3);  // 0.5 s at full trigger
  EXPECT_NEAR(control.state().tip.x(), 0.01, 1e-9);
  EXPECT_EQ(control.state().inflow, 1.0) << "A toggled the inflow valve once";
  virtual_pad.button(SDL_CONTROLLER_BUTTON_A, false);
  virtual_pad.axis(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, -32768);
  for (int i = 0; i < 100; ++i)
    input.next(1e-3);
  EXPECT_NEAR(control.state().tip.x(), 0.01, 1e-9) << "released trigger stops the tool";
  EXPECT_EQ(control.state().inflow, 1.0);
  EXPECT_NE(input.describe().find("Viscera test pad"), std::string::npos);
}

TEST(SdlGamepad, without_a_pad_it_says_so_and_the_keyboard_still_drives) {
  SdlGamepad pad;  // the test machine has no pad; a virtual one is detached by now
  if (pad.connected()) GTEST_SKIP() << "a real gamepad is plugged in: " << pad.name();
  EXPECT_FALSE(pad.read().has_value());
  ManualControl control(InstrumentState{});
  GamepadInput input(control, pad);
  control.press(ManualCommand::Advance);
  input.next(0.5);
  EXPECT_NEAR(control.state().tip.z(), 0.005, 1e-12);  // 0.01 m/s along +z
  EXPECT_EQ(input.describe(), "no gamepad found: keyboard and mouse");
}

}  // namespace
}  // namespace viscera::sim

#endif  // VISCERA_HAVE_SDL2
