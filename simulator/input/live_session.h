#pragma once
/// A session driven by a live input without a window (`viscera-sim run --headless --input
/// udp:PORT`): physics steps paced by the wall clock, the input polled before and told after
/// every step. The runner records each state it is given, so the trace replays bit for bit.

#include "core/scenario/scenario.h"
#include "simulator/input/live_input.h"
#include "simulator/session/session_runner.h"

namespace viscera::sim {

/// Runs `options`' session with `input` driving the instrument (options.instrument is
/// replaced), one physics step whenever the simulated time falls behind the wall clock, until
/// the session ends (duration, completion, perforation or the input's abort).
SessionReport run_live(const core::Scenario& scenario, const HeadlessRunOptions& options,
                       LiveInput& input);

}  // namespace viscera::sim
