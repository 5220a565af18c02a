#pragma once
/// Typed simulation failures (issue 16 item 6): when the physics of a session cannot go on, the
/// error names the body, the node, the physics step and the likely cause instead of a bare
/// message. The session runner checks the state after every step it samples and turns any error
/// the world throws while stepping into a core::SimulationError through these functions.

#include <optional>
#include <string>

#include "core/error.h"
#include "core/scenario/scenario.h"
#include "simulator/world/world.h"

namespace viscera::sim {

/// What is wrong with a world's state, if anything.
struct StateFault {
  std::string body;         ///< name of the first faulty body
  long long node = -1;      ///< its first node with a non-finite position, −1 when all finite
  int inverted_tets = 0;    ///< tets of that body turned inside out since rest
  bool non_finite = false;  ///< a position is NaN or infinite
};

/// Looks over every body of `world` in order for a node with a non-finite position; for that
/// body also counts its tets whose signed volume has changed sign since rest. nullopt when
/// every position is finite.
std::optional<StateFault> find_state_fault(const World& world);

/// The error for `fault` found at physics step `step`: "the simulation became unstable at
/// step S (t = T s): node N of body B has a non-finite position" with the likely cause —
/// inverted tets (the tissue crushed through itself) or a step too large for the material.
core::SimulationError simulation_error(const StateFault& fault, long long step, double time);

/// The error for a failure `what` the world reported at physics step `step` (e.g. a solver
/// that did not converge) when its state shows no fault: names `body` when known.
core::SimulationError simulation_error(const std::string& what, const std::string& body,
                                       long long step, double time);

}  // namespace viscera::sim
