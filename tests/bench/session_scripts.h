#pragma once
/// The hysteroscopy patient and instrument scripts the session benchmarks drive
/// (session_bench.cpp, soak_bench.cpp).

#include <nlohmann/json.hpp>
#include <string>

#include "core/scenario/scenario.h"
#include "simulator/session/instrument_input.h"
#include "simulator/session/session_runner.h"

namespace viscera::bench {

/// `viscera new --template hysteroscopy --seed 1`, built once.
const core::Scenario& hysteroscopy_patient();

/// data/scripts/hysteroscopy-`who`.json with its landmark places resolved on the patient.
nlohmann::json hysteroscopy_script(const std::string& who);

/// The script's waypoints repeated back to back (0.5 s apart) until `seconds`.
nlohmann::json repeated(nlohmann::json script, double seconds);

/// Headless options for `input` driving the instrument for `duration` s; the session goes on
/// after the procedure's tasks are done (a tour, a soak).
sim::HeadlessRunOptions scripted_run(const sim::ScriptedTrajectory& input, double duration);

}  // namespace viscera::bench
