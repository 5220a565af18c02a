#pragma once
/// Live input sources of a session (issue 8 items 1, 7, 9): the keyboard and mouse, a gamepad,
/// a haptic device over UDP. Each is asked once per physics step for the instrument state; the
/// session runner records every state it is given in the trace, so a live session replays bit
/// for bit from its trace like a scripted one.

#include <string>

#include "simulator/session/instrument_input.h"
#include "simulator/session/manual_control.h"

namespace viscera::sim {

class SessionRunner;
struct RealtimeStats;

/// A source of instrument states polled in real time.
class LiveInput {
 public:
  virtual ~LiveInput() = default;
  /// The state for the next physics step of `dt` s: reads the source and moves the instrument.
  virtual InstrumentState next(double dt) = 0;
  /// The state last returned (or the starting state before the first step).
  virtual const InstrumentState& current() const = 0;
  /// Called after each physics step, e.g. to send force feedback to a device.
  virtual void after_step(const SessionRunner&) {}
  /// One line naming the source and its state, for the window and the console.
  virtual std::string describe() const = 0;
  /// A threaded session (RealtimeLoop) calls this before its physics thread starts and
  /// stop_realtime() after it stopped: a source with its own I/O (a haptic device) moves it to
  /// its own thread here; next() and after_step() are then called on the physics thread.
  virtual void start_realtime(const SessionRunner&) {}
  virtual void stop_realtime() {}
  /// Adds the source's own counters (device poses, feedback) to a threaded session's stats.
  virtual void add_stats(RealtimeStats&) const {}
};

/// The keyboard and mouse: the window feeds `control`, this reads it.
class KeyboardInput final : public LiveInput {
 public:
  explicit KeyboardInput(ManualControl& control) : control_(control) {}
  InstrumentState next(double dt) override { return control_.advance(dt); }
  const InstrumentState& current() const override { return control_.state(); }
  std::string describe() const override { return "keyboard and mouse"; }

 private:
  ManualControl& control_;
};

/// A live input seen as a session's InstrumentInput: the runner attaches the instrument at the
/// source's current state (the states of later steps come from LiveInput::next).
class LiveInstrument final : public InstrumentInput {
 public:
  explicit LiveInstrument(const LiveInput& live) : live_(live) {}
  InstrumentState state(long long, double) const override { return live_.current(); }

 private:
  const LiveInput& live_;
};

}  // namespace viscera::sim
