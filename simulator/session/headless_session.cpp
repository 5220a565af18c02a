#include "simulator/session/headless_session.h"

#include <cmath>

namespace viscera::sim {

SessionReport run_headless(const core::Scenario& scenario, const HeadlessRunOptions& options,
                           core::Progress& progress) {
  SessionRunner runner(scenario, options);
  const auto total =
      static_cast<long long>(std::llround(runner.time_limit() / runner.world().time_step()));
  progress.begin_stage("simulating", total);
  while (!runner.finished()) {
    const long long next = runner.world().steps() + 1;
    const double time = static_cast<double>(next) * runner.world().time_step();
    runner.step(options.instrument != nullptr ? options.instrument->state(next, time)
                                              : InstrumentState{});
    progress.step();
  }
  return runner.finish();
}

}  // namespace viscera::sim
