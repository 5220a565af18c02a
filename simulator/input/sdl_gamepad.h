#pragma once
/// Gamepads through SDL2's game-controller API (issue 8 item 1): the first pad SDL knows is
/// read into a GamepadState and mapped (gamepad_mapping.h) onto the same ManualControl the
/// keyboard drives, so both work at once and the session records only instrument states.
/// SDL runs without a window of its own: events are off and the state is polled.

#include <optional>
#include <string>

#include "simulator/input/gamepad_mapping.h"
#include "simulator/input/live_input.h"

struct _SDL_GameController;

namespace viscera::sim {

/// The first connected game controller, opened on demand.
class SdlGamepad {
 public:
  /// Starts SDL's game-controller subsystem and opens the first pad, if any. Throws
  /// core::Error when SDL cannot start it.
  SdlGamepad();
  ~SdlGamepad();
  SdlGamepad(const SdlGamepad&) = delete;
  SdlGamepad& operator=(const SdlGamepad&) = delete;

  /// Polls SDL: drops a pad that was unplugged, opens the first one plugged in, and returns
  /// its state (sticks and triggers scaled to [−1, 1] and [0, 1]); nullopt without a pad.
  std::optional<GamepadState> read();
  bool connected() const { return pad_ != nullptr; }
  /// The pad's name as SDL reports it (empty without a pad).
  std::string name() const;

 private:
  void open_first();
  _SDL_GameController* pad_ = nullptr;
};

/// A gamepad and the keyboard driving one ManualControl.
class GamepadInput final : public LiveInput {
 public:
  /// `dead_zone` as in map_gamepad; the pad is read at most every `read_interval` s of session.
  GamepadInput(ManualControl& control, SdlGamepad& pad, double dead_zone = 0.15,
               double read_interval = 0.005);
  InstrumentState next(double dt) override;
  const InstrumentState& current() const override { return control_.state(); }
  std::string describe() const override;

 private:
  ManualControl& control_;
  SdlGamepad& pad_;
  double dead_zone_, read_interval_, since_read_;
  GamepadState previous_;
};

}  // namespace viscera::sim
