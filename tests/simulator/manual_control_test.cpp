// Keyboard and mouse control of the instrument: exact motions for held keys, toggles, abort, and
// the two hands of a laparoscopy (the working port and the second port).

#include "simulator/session/manual_control.h"

#include <gtest/gtest.h>

#include <numbers>

namespace viscera::sim {
namespace {

TEST(ManualControl, held_keys_move_the_tip_along_the_shaft_at_the_set_rate) {
  InstrumentState start;
  start.tip = core::Vec3(0.01, 0.0, 0.0);
  start.axis = core::Vec3::UnitX();
  start.up = core::Vec3::UnitZ();
  ManualRates rates;
  rates.advance = 0.02;
  ManualControl control(start, rates);
  control.press(*ManualControl::command_for_key("w"));
  for (int i = 0; i < 500; ++i)
    control.advance(1e-3);  // 0.5 s
  EXPECT_NEAR(control.state().tip.x(), 0.01 + 0.02 * 0.5, 1e-12);
  control.release(ManualCommand::Advance);
  control.advance(1.0);
  EXPECT_NEAR(control.state().tip.x(), 0.02, 1e-12) << "released keys stop the motion";
  control.press(ManualCommand::Withdraw);
  control.advance(0.25);
  EXPECT_NEAR(control.state().tip.x(), 0.015, 1e-12);
}

TEST(ManualControl, pedals_act_while_held_and_the_loop_travels_within_its_range) {
  ManualRates rates;
  rates.loop = 0.01;
  ManualControl control(InstrumentState{}, rates);
  control.press(*ManualControl::command_for_key("space"));
  EXPECT_TRUE(control.state().electrode);
  control.release(ManualCommand::CuttingPedal);
  EXPECT_FALSE(control.state().electrode);
  control.press(*ManualControl::command_for_key("c"));
  EXPECT_TRUE(control.state().coagulation);
  control.release(ManualCommand::CoagulationPedal);
  EXPECT_FALSE(control.state().coagulation);
  // L holds the suction–irrigation cannula's irrigation valve open; switching tools shuts it.
  control.press(*ManualControl::command_for_key("l"));
  EXPECT_TRUE(control.state().irrigating);
  control.release(ManualCommand::Irrigate);
  EXPECT_FALSE(control.state().irrigating);
  control.press(ManualCommand::Irrigate);
  control.press(ManualCommand::ToolGrasper);
  EXPECT_FALSE(control.state().irrigating);
  control.press(*ManualControl::command_for_key("t"));
  control.advance(0.5);
  EXPECT_NEAR(control.state().loop_extension, 0.005, 1e-15);
  control.advance(10.0);
  EXPECT_EQ(control.state().loop_extension, kMaxLoopExtension);  // the working element's stop
  control.release(ManualCommand::ExtendLoop);
  control.press(*ManualControl::command_for_key("g"));
  control.advance(0.5);
  EXPECT_NEAR(control.state().loop_extension, kMaxLoopExtension - 0.005, 1e-15);
  control.advance(10.0);
  EXPECT_EQ(control.state().loop_extension, 0.0);
  EXPECT_EQ(control.state().tip, core::Vec3::Zero());  // the loop moves, not the sheath
}

TEST(ManualControl, swing_and_roll_turn_by_rate_times_time_and_keep_a_frame) {
  InstrumentState start;
  start.axis = core::Vec3::UnitX();
  start.up = core::Vec3::UnitZ();
  ManualRates rates;
  rates.swing = std::numbers::pi / 2.0;
  rates.roll = std::numbers::pi / 2.0;
  ManualControl control(start, rates);
  control.press(ManualCommand::SwingLeft);
  control.advance(1.0);  // a quarter turn to the left about +z: x → y
  EXPECT_NEAR((control.state().axis - core::Vec3::UnitY()).norm(), 0.0, 1e-12);
  EXPECT_NEAR((control.state().up - core::Vec3::UnitZ()).norm(), 0.0, 1e-12);
  control.release(ManualCommand::SwingLeft);
  control.press(ManualCommand::RollLeft);
  control.advance(1.0);  // a quarter roll about the shaft (+y): up z → x
  EXPECT_NEAR((control.state().axis - core::Vec3::UnitY()).norm(), 0.0, 1e-12);
  EXPECT_NEAR((control.state().up - core::Vec3::UnitX()).norm(), 0.0, 1e-12);
  EXPECT_NEAR(control.state().axis.dot(control.state().up), 0.0, 1e-12);
  // 30° optics look between the shaft and the rolled-up side.
  const core::Vec3 view = view_direction(control.state(), 30.0);
  EXPECT_NEAR(view.dot(core::Vec3::UnitY()), std::cos(std::numbers::pi / 6.0), 1e-12);
  EXPECT_NEAR(view.dot(core::Vec3::UnitX()), 0.5, 1e-12);
}

TEST(ManualControl, valves_toggle_abort_latches_and_unknown_keys_do_nothing) {
  ManualControl control(InstrumentState{});
  EXPECT_FALSE(ManualControl::command_for_key("z").has_value());
  control.press(*ManualControl::command_for_key("i"));
  EXPECT_EQ(control.state().inflow, 1.0);
  control.press(ManualCommand::ToggleInflow);
  EXPECT_EQ(control.state().inflow, 0.0);
  control.press(*ManualControl::command_for_key("o"));
  EXPECT_EQ(control.state().outflow, 1.0);
  EXPECT_FALSE(control.state().abort);
  control.press(*ManualControl::command_for_key("Escape"));
  EXPECT_TRUE(control.state().abort);
  control.wheel(3);
  EXPECT_NEAR(control.state().tip.z(), 0.003, 1e-12) << "the shaft starts along +z";
  EXPECT_NE(ManualControl::bindings_text().find("Esc"), std::string::npos);
}

TEST(ManualControl, tab_puts_the_left_hands_tool_in_and_the_keys_then_move_it_alone) {
  InstrumentState start;
  start.tip = core::Vec3(0.0, 0.0, 0.1);
  start.axis = -core::Vec3::UnitZ();
  start.up = core::Vec3::UnitY();
  ManualRates rates;
  rates.advance = 0.02;
  ManualControl control(start, rates);
  EXPECT_FALSE(control.state().second.inserted);
  control.press(*ManualControl::command_for_key("Tab"));
  EXPECT_EQ(control.hand(), 1);
  const SecondPort entered = control.state().second;
  ASSERT_TRUE(entered.inserted);
  EXPECT_EQ(entered.tool, LaparoscopicTool::Grasper);
  // From a trocar 3 cm to the image's left, its tip half-way to 5 cm in front of the optics.
  EXPECT_NEAR((entered.tip - core::Vec3(-0.015, 0.0, 0.075)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(entered.axis.dot(core::Vec3(0.03, 0.0, -0.05).normalized()), 1.0, 1e-12);
  // The keys now move, switch and close the left hand's tool; the right hand stays put.
  control.press(ManualCommand::Advance);
  control.advance(0.5);
  control.release(ManualCommand::Advance);
  control.press(ManualCommand::ToolBipolar);
  control.press(ManualCommand::CloseJaws);
  const InstrumentState& s = control.state();
  EXPECT_NEAR((s.second.tip - entered.tip - 0.01 * entered.axis).norm(), 0.0, 1e-12);
  EXPECT_EQ(s.second.tool, LaparoscopicTool::Bipolar);
  EXPECT_TRUE(s.second.jaws_closed);
  EXPECT_EQ(s.tip, start.tip);
  EXPECT_EQ(s.tool, LaparoscopicTool::None);
  EXPECT_FALSE(s.jaws_closed);
  // Back to the right hand: the left tool stays where it was, jaws still closed.
  control.press(ManualCommand::SwitchHand);
  EXPECT_EQ(control.hand(), 0);
  control.press(ManualCommand::Advance);
  control.advance(0.5);
  EXPECT_NEAR(control.state().tip.z(), 0.09, 1e-12);
  EXPECT_TRUE(control.state().second.jaws_closed);
  EXPECT_NEAR((control.state().second.tip - s.second.tip).norm(), 0.0, 1e-15);
  // Backspace takes it out.
  control.press(*ManualControl::command_for_key("BackSpace"));
  EXPECT_FALSE(control.state().second.inserted);
  EXPECT_EQ(control.hand(), 0);
}

}  // namespace
}  // namespace viscera::sim
