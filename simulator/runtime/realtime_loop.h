#pragma once
/// The interactive runtime of a windowed session (DESIGN.md §5, issue 16 item 3): the session's
/// physics on its own thread at the scenario's step, paced by the wall clock; the input's own
/// threads beside it (a haptic device's I/O at ≥ 1 kHz, HapticDeviceLoop); and the view reading
/// lock-free snapshots (TripleBuffer) at display rate. Every step goes through
/// SessionRunner::step with the state the input gave, so the session's trace replays
/// bit-identically headless, where the same runner steps on one thread.

#include <atomic>
#include <exception>
#include <mutex>
#include <string>
#include <thread>

#include "simulator/input/live_input.h"
#include "simulator/runtime/session_snapshot.h"
#include "simulator/runtime/triple_buffer.h"
#include "simulator/session/session_runner.h"

namespace viscera::sim {

/// Counters of the physics thread, readable from any thread.
struct RealtimeCounters {
  std::atomic<long long> physics_steps{0};
  std::atomic<long long> late_steps{0};  ///< steps that began more than one step late
  std::atomic<long long> slowdowns{0};   ///< times the session fell > 0.1 s behind and slowed
  std::atomic<long long> snapshots{0};   ///< snapshots handed to the view
};

/// A session stepped in real time on its own thread.
class RealtimeLoop {
 public:
  /// Steps `runner` with the state `live` gives for each step (asked on the physics thread,
  /// its start_realtime/stop_realtime hooks run around the loop), or, without `live`, the
  /// state of `scripted` for each step (null: no instrument). All must outlive the loop.
  RealtimeLoop(SessionRunner& runner, LiveInput* live, const InstrumentInput* scripted);
  ~RealtimeLoop();
  RealtimeLoop(const RealtimeLoop&) = delete;
  RealtimeLoop& operator=(const RealtimeLoop&) = delete;

  /// Starts the physics thread (and the input's). The runner belongs to that thread until
  /// join() returns.
  void start();
  /// Asks the physics thread to end the session with `reason` and `message` before its next
  /// step (e.g. "abort" from the window). Any thread.
  void request_end(const std::string& reason, const std::string& message);
  /// True once the physics thread has stopped (the session ended or failed). Any thread.
  bool finished() const { return finished_.load(std::memory_order_acquire); }
  /// Waits for the physics thread, stops the input's threads and rethrows what the physics
  /// raised (e.g. core::SimulationError). Call request_end() first unless finished().
  void join();

  /// The view's thread: the newest snapshot, or null when none is newer than the last call's.
  /// The pointer stays valid until the next call. Asking also tells the physics thread to
  /// capture the next one, so snapshots are taken at the view's rate, not the physics'.
  const SessionSnapshot* latest();

  const RealtimeCounters& counters() const { return counters_; }
  /// Niceness the physics thread asks for (higher share of a contended core than the view).
  static constexpr int kPhysicsNice = -5;
  /// Largest delay in s of a step behind its wall-clock due time.
  double max_lag() const { return max_lag_.load(std::memory_order_relaxed); }
  /// Wall-clock seconds the physics thread ran.
  double wall_time() const { return wall_time_.load(std::memory_order_relaxed); }

 private:
  void physics_thread();
  void publish_snapshot();

  SessionRunner& runner_;
  LiveInput* live_;
  const InstrumentInput* scripted_;
  TripleBuffer<SessionSnapshot> snapshots_;
  std::atomic<bool> wanted_{true};
  RealtimeCounters counters_;
  std::atomic<double> max_lag_{0.0}, wall_time_{0.0};
  std::atomic<bool> end_requested_{false}, finished_{false};
  std::mutex end_mutex_;  ///< guards the reason below (written once, read by the physics)
  std::string end_reason_, end_message_;
  std::exception_ptr failure_;
  std::thread thread_;
  bool started_ = false;
};

}  // namespace viscera::sim
