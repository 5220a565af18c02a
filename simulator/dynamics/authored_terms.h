#pragma once
/// What a clinician authors beyond bodies and materials, as terms of the simulation core (issue
/// 16, "everything authored is simulated"): the world calls these while it builds.
///   - cell-agent objects (seed 003 §V) become bodies of the state with an AgentTissueTerm;
///   - every tet or mass-spring body gets PlasticFlow (its materials' plastic_yield) and
///     TissueTearing (their tearing_threshold) on its distance terms or KisMo springs;
///   - each active deformation becomes MotilityForces (seed 001 §5.2) or PulseWaves along its
///     vessel tree (§5.1.1) on its target object's body.

#include <memory>
#include <vector>

#include "core/scenario/scenario.h"
#include "simulator/dynamics/body_model.h"
#include "simulator/dynamics/force_term.h"
#include "simulator/dynamics/tissue_tearing.h"

namespace viscera::sim {

/// Adds the cells of `object` (body kind CellAgent; its body nodes are the homes, with their
/// masses and fixed flags, its surface faces what the instrument touches) as a body of `state`
/// and returns its model. Throws core::InputError naming the object when the scenario has no
/// cell tissue for it, a node has no mass or a free node no positive mass, or its material is
/// unknown.
std::shared_ptr<BodyModel> add_cell_agent_body(const core::Scenario& scenario,
                                               const core::SceneObject& object,
                                               SimulationState& state);

/// The authored terms for the bodies of `models` (indexed by body) whose built-in terms are
/// `terms` (plastic flow and tearing attach to their distance terms and KisMo springs, so they
/// must stay alive and in front). `time_step` s is the session's step. Throws core::InputError
/// naming the active deformation whose target has no body, whose vessel tree is missing, or
/// whose spec is unusable.
std::vector<std::unique_ptr<ForceTerm>> authored_terms(
    const core::Scenario& scenario, const SimulationState& state,
    const std::vector<std::shared_ptr<BodyModel>>& models,
    const std::vector<std::unique_ptr<ForceTerm>>& terms, double time_step);

/// True when `terms` hold a term that moves bodies by itself (motility, pulse): such a world
/// must never fall asleep.
bool drives_bodies(const std::vector<std::unique_ptr<ForceTerm>>& terms);

/// Every tear recorded by the tearing and cell-agent terms of `terms`, by time (stable).
std::vector<TearEvent> tears_of(const std::vector<std::unique_ptr<ForceTerm>>& terms);

/// How many tears tears_of would list, without copying or sorting them: what a caller checks
/// after every step before it looks at new tears.
std::size_t tear_count(const std::vector<std::unique_ptr<ForceTerm>>& terms);

}  // namespace viscera::sim
