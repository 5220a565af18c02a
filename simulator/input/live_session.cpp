#include "simulator/input/live_session.h"

#include <chrono>
#include <thread>

namespace viscera::sim {

SessionReport run_live(const core::Scenario& scenario, const HeadlessRunOptions& options,
                       LiveInput& input) {
  const LiveInstrument instrument(input);
  HeadlessRunOptions run = options;
  run.instrument = &instrument;
  SessionRunner runner(scenario, run);
  using clock = std::chrono::steady_clock;
  const double dt = runner.world().time_step();
  const auto start = clock::now();
  while (!runner.finished()) {
    // The wall-clock moment step n+1 is due; sleeping until then paces the session.
    const auto due = start + std::chrono::duration_cast<clock::duration>(
                                 std::chrono::duration<double>(runner.world().time()));
    std::this_thread::sleep_until(due);
    runner.step(input.next(dt));
    input.after_step(runner);
  }
  return runner.finish();
}

}  // namespace viscera::sim
