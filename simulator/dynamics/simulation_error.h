#pragma once
/// Errors the simulation raises: a non-finite state or an inverted element, naming body, node
/// (or tet) and step. Built in one place so the error type can become core::SimulationError.

#include <string>

#include "core/error.h"

namespace viscera::sim {

/// "simulation became unstable: <reason> at step N (t = … s)" located at body and node.
core::Error simulation_error(const std::string& reason, const std::string& body,
                             const std::string& element, long long step, double time);

}  // namespace viscera::sim
