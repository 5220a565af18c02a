#pragma once
// A viscera-script built in a test, and the message a bad one is refused with.

#include <nlohmann/json.hpp>
#include <string>

#include "core/error.h"
#include "simulator/session/instrument_input.h"

namespace viscera::testing {

/// A version-2 script with `waypoints`.
inline nlohmann::json script(nlohmann::json waypoints) {
  return {{"format", "viscera-script"}, {"version", 2}, {"waypoints", std::move(waypoints)}};
}

/// The InputError a script named "s.json" is refused with (optics at 30°), or "accepted".
inline std::string input_error(const nlohmann::json& json) {
  try {
    sim::ScriptedTrajectory::from_json(json, "s.json", 30.0);
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "accepted";
}

}  // namespace viscera::testing
