#include "simulator/runtime/realtime_loop.h"

#include <sys/resource.h>
#include <unistd.h>

#include <chrono>

namespace viscera::sim {

namespace {
/// A session more than this far behind the wall clock slows down instead of racing to catch
/// up (s): a slow machine gives a slower session, never a burst of steps.
constexpr double kMaxLag = 0.1;
}  // namespace

RealtimeLoop::RealtimeLoop(SessionRunner& runner, LiveInput* live, const InstrumentInput* scripted)
    : runner_(runner), live_(live), scripted_(scripted) {}

RealtimeLoop::~RealtimeLoop() {
  if (thread_.joinable()) {
    request_end("abort", "the session was stopped");
    thread_.join();
  }
  if (started_ && live_ != nullptr) live_->stop_realtime();
}

void RealtimeLoop::start() {
  if (started_) return;
  started_ = true;
  if (live_ != nullptr) live_->start_realtime(runner_);
  thread_ = std::thread([this] { physics_thread(); });
}

void RealtimeLoop::request_end(const std::string& reason, const std::string& message) {
  {
    const std::lock_guard<std::mutex> lock(end_mutex_);
    if (end_requested_.load()) return;
    end_reason_ = reason;
    end_message_ = message;
  }
  end_requested_.store(true, std::memory_order_release);
}

void RealtimeLoop::join() {
  if (thread_.joinable()) thread_.join();
  if (started_ && live_ != nullptr) {
    live_->stop_realtime();
    started_ = false;
  }
  if (failure_) std::rethrow_exception(failure_);
}

const SessionSnapshot* RealtimeLoop::latest() {
  const bool fresh = snapshots_.update();
  wanted_.store(true, std::memory_order_release);
  return fresh ? &snapshots_.read_slot() : nullptr;
}

void RealtimeLoop::publish_snapshot() {
  capture_snapshot(runner_, snapshots_.write_slot());
  snapshots_.publish();
  counters_.snapshots.fetch_add(1, std::memory_order_relaxed);
}

void RealtimeLoop::physics_thread() {
  // The physics keeps the session's clock: when the renderer's threads and the physics want
  // the same core, the physics gets the larger share (nice −5, best effort; it sleeps whenever
  // it is ahead of the wall clock, so the view keeps the rest).
  setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), kPhysicsNice);
  using clock = std::chrono::steady_clock;
  const double dt = runner_.world().time_step();
  const auto began = clock::now();
  // Wall-clock moment at which the simulated time `t0` was (or is) due.
  auto origin = began;
  const double t0 = runner_.world().time();
  try {
    while (!runner_.finished()) {
      if (end_requested_.load(std::memory_order_acquire)) {
        const std::lock_guard<std::mutex> lock(end_mutex_);
        runner_.end(end_reason_, end_message_);
        break;
      }
      // Step n+1 is due once the wall clock reaches the simulated time of step n.
      const auto due = origin + std::chrono::duration_cast<clock::duration>(
                                    std::chrono::duration<double>(runner_.world().time() - t0));
      const auto now = clock::now();
      if (now < due) {
        std::this_thread::sleep_until(due);
      } else {
        const double lag = std::chrono::duration<double>(now - due).count();
        if (lag > dt) counters_.late_steps.fetch_add(1, std::memory_order_relaxed);
        if (lag > max_lag_.load(std::memory_order_relaxed))
          max_lag_.store(lag, std::memory_order_relaxed);
        if (lag > kMaxLag) {
          origin += now - due;  // slow the session down by the time lost
          counters_.slowdowns.fetch_add(1, std::memory_order_relaxed);
        }
      }
      const long long next = runner_.world().steps() + 1;
      const InstrumentState state = live_ != nullptr ? live_->next(dt)
                                    : scripted_ != nullptr
                                        ? scripted_->state(next, static_cast<double>(next) * dt)
                                        : InstrumentState{};
      runner_.step(state);
      if (live_ != nullptr) live_->after_step(runner_);
      counters_.physics_steps.fetch_add(1, std::memory_order_relaxed);
      if (wanted_.exchange(false, std::memory_order_acq_rel)) publish_snapshot();
    }
  } catch (...) {
    failure_ = std::current_exception();
  }
  publish_snapshot();  // the final state, with its end reason
  wall_time_.store(std::chrono::duration<double>(clock::now() - began).count());
  finished_.store(true, std::memory_order_release);
}

}  // namespace viscera::sim
