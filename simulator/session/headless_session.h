#pragma once
/// A session run without a window at a fixed physics step (DESIGN.md §5, deterministic mode):
/// a SessionRunner driven by a scripted or recorded input until an end condition holds.

#include "core/progress.h"
#include "core/scenario/scenario.h"
#include "simulator/session/session_runner.h"

namespace viscera::sim {

/// Runs `scenario` headless for at most options.duration seconds (and the scenario's time
/// limit) with options.instrument as the input. Tasks are watched and scored as the
/// procedure says; a task the runtime cannot detect is reported "unavailable" with the
/// reason. Throws core::Error subclasses.
SessionReport run_headless(const core::Scenario& scenario, const HeadlessRunOptions& options,
                           core::Progress& progress = core::Progress::none());

}  // namespace viscera::sim
