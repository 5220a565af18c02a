#pragma once
/// The instrument under the trainee's hands when no device is connected: keyboard and mouse
/// move the tip along the shaft, swing the shaft, roll the angled optics and open the valves
/// (seed 002 §6: the keyboard as the input device for fast testing). The window only maps
/// events to commands; the motion is plain arithmetic on an InstrumentState, so it is tested
/// without a display.

#include <optional>
#include <string>

#include "core/scenario/scenario.h"
#include "simulator/session/instrument_state.h"

namespace viscera::sim {

/// What a key or button asks for.
enum class ManualCommand {
  Advance,    ///< tip forward along the shaft
  Withdraw,   ///< tip backward along the shaft
  SwingLeft,  ///< shaft yaw about the image's up
  SwingRight,
  SwingUp,  ///< shaft pitch towards the image's up
  SwingDown,
  RollLeft,  ///< optics rolled about the shaft (the 30° view sweeps round)
  RollRight,
  ExtendLoop,        ///< the resection loop out in front of the sheath
  RetractLoop,       ///< the loop back towards the sheath (the cutting stroke)
  CuttingPedal,      ///< held: the loop's cutting current is on
  CoagulationPedal,  ///< held: the loop's coagulating current is on
  ToggleInflow,      ///< inflow valve open ↔ closed
  ToggleOutflow,     ///< outflow valve open ↔ closed
  CloseJaws,         ///< held: the laparoscopic tool's jaws are closed (the suction valve)
  Irrigate,          ///< held: the suction–irrigation cannula's irrigation valve is open
  ToolNone,          ///< the working port empty (the bare optics shaft)
  ToolGrasper,       ///< a grasper in the working port
  ToolClipApplier,   ///< a clip applier
  ToolScissors,      ///< scissors
  ToolBipolar,       ///< bipolar forceps
  ToolSuction,       ///< a suction cannula
  ToolHook,          ///< a monopolar L-hook
  NextTool,          ///< the next tool in the order above (after the hook: none)
  PreviousTool,      ///< the previous one
  /// The keys, mouse and gamepad move the other hand: the working port's tool (the right hand,
  /// which carries the laparoscope) or the second port's (the left hand). The first switch to
  /// the left hand puts a grasper into the second port (second_port_entry).
  SwitchHand,
  WithdrawSecondTool,  ///< the second port's tool out of the abdomen (the right hand again)
  /// The keys, mouse and gamepad move the laparoscope (the camera) apart from the working port;
  /// the first time, it is taken up where the working port's optics are, so the view stays.
  /// The tools' switches still act on the hand last moved; SwitchHand goes back to the tools.
  TakeCamera,
  Abort  ///< the trainee ends the session
};

/// Motion rates of the manual controls.
struct ManualRates {
  double advance = 0.01;  ///< m/s while an advance key is held
  double swing = 0.5;     ///< rad/s while a swing key is held
  double roll = 1.0;      ///< rad/s while a roll key is held
  double loop = 0.01;     ///< m/s of loop travel while a loop key is held
  double mouse = 0.005;   ///< rad per pixel of mouse drag
  double wheel = 0.001;   ///< m per wheel notch
};

/// Proportional motion from an analogue input (a gamepad's sticks and triggers): each in
/// [−1, 1] as a fraction of the ManualRates, added to the held keys' ±1 and clamped to ±1.
struct AnalogMotion {
  double advance = 0.0;  ///< + advance, − withdraw
  double yaw = 0.0;      ///< + swing left (as SwingLeft)
  double pitch = 0.0;    ///< + swing up (as SwingUp)
  double roll = 0.0;     ///< + roll left (as RollLeft)
  bool operator==(const AnalogMotion&) const = default;
};

/// Keyboard, mouse and gamepad instrument control.
class ManualControl {
 public:
  explicit ManualControl(const InstrumentState& start, ManualRates rates = {});

  /// The command bound to an X key symbol (e.g. "w", "Up", "Escape"), if any.
  static std::optional<ManualCommand> command_for_key(const std::string& key);
  /// The bindings as the window shows them, one line each.
  static std::string bindings_text();

  /// A key went down / up. Held motions act in advance(); pedals act while held; toggles and
  /// abort act at once.
  void press(ManualCommand command);
  void release(ManualCommand command);
  /// A mouse drag of (dx, dy) pixels with the left button swings the shaft.
  void drag(double dx, double dy);
  /// Wheel notches (positive: forward) move the tip along the shaft.
  void wheel(int notches);

  /// Sets the proportional motion that acts in advance() until set again.
  void set_analog(const AnalogMotion& motion) { analog_ = motion; }

  /// Applies the held motions for `dt` s and returns the state.
  const InstrumentState& advance(double dt);
  const InstrumentState& state() const { return state_; }
  /// What the controls move: 0 the right hand (working port), 1 the left (second port), 2 the
  /// laparoscope held as the camera.
  int hand() const { return hand_; }

 private:
  /// The pose and controls the keys act on: the working port's, or the second port's tool
  /// as an instrument state (copied back into state_.second by sync_second()).
  InstrumentState& held_tool() { return tool_hand_ == 0 ? state_ : left_; }
  /// The pose the motions act on: the held tool's, or the camera's (copied back by sync_second).
  InstrumentState& moved() { return hand_ == 2 ? camera_ : held_tool(); }
  void sync_second();
  void swing(double yaw, double pitch);
  void roll(double angle);

  InstrumentState state_;
  InstrumentState left_;    ///< the second port's tool while it is in
  InstrumentState camera_;  ///< the laparoscope's pose once taken up
  int hand_ = 0;
  int tool_hand_ = 0;  ///< the tool the switches act on: the hand last moved (0 or 1)
  ManualRates rates_;
  bool held_[static_cast<int>(ManualCommand::CuttingPedal)] = {};
  AnalogMotion analog_;
};

/// Where the second port's tool enters when a trainee first takes the left hand: a grasper
/// from a trocar 3 cm to the left of the laparoscope (in the image), its tip half-way to the
/// point 5 cm in front of the optics, so it comes into view.
SecondPort second_port_entry(const InstrumentState& laparoscope);

/// Where a manual session starts: 3 mm off the landmark "cervix-internal-os" (else the first
/// landmark) along its normal, the optics looking at the mean of the other landmarks (those of the
/// cervix excepted); without
/// landmarks, at the centre of the first simulated object's bounding box looking along +z.
InstrumentState starting_pose(const core::Scenario& scenario, double optics_angle);

}  // namespace viscera::sim
