#pragma once
/// Authoring side of active deformation (seed 001 §5): pulse waves on vessel trees (§5.1.1:
/// heart rate, mean pulse velocity per vessel, forces on the vessel walls) and organ motility
/// (§5.2: amplitude mean and variance, wave speed and direction, frequency and its disturbance,
/// impulsive contractions with mean and variance timing). These functions check specs as data;
/// the runtime that plays them belongs to the simulator. "Per vessel" velocities are one
/// PulseSpec per vessel tree, as KisMo modelled each vessel as its own pipe object.

#include <string>
#include <vector>

#include "core/scenario/scenario.h"

namespace viscera::textures {

/// One finding, with the JSON pointer of the member in the package manifest. Errors make a spec
/// unusable; warnings flag values outside the physiological range the seed's sources give.
struct SpecIssue {
  std::string json_pointer;
  std::string message;
  bool error = true;

  bool operator==(const SpecIssue&) const = default;
};

/// Checks a pulse spec; `pointer` is where it sits (e.g. "/scenario/active_deformations/0/pulse").
/// With a scenario, the vessel tree must exist there, and the seed's warning case is reported:
/// a wave that needs longer than one beat to cross the tree is cut off by the next beat.
std::vector<SpecIssue> validate_pulse_spec(const core::PulseSpec& spec,
                                           const core::Scenario* scenario,
                                           const std::string& pointer);

/// Checks a motility spec (units of core::MotilitySpec).
std::vector<SpecIssue> validate_motility_spec(const core::MotilitySpec& spec,
                                              const std::string& pointer);

/// Checks every active deformation of a scenario: unique ids, a target object that exists, at
/// most one pulse per vessel tree, and each spec as above.
std::vector<SpecIssue> validate_active_deformations(const core::Scenario& scenario);

/// Length in m of the longest root-to-terminal path of a tree: how far a pulse wave travels.
double longest_wave_path(const core::VesselTree& tree);

/// A pulse on `tree`, checked; throws core::ValidationError with the first error's pointer.
core::ActiveDeformation make_pulse(const std::string& id, const std::string& target_object,
                                   const core::VesselTree& tree, double heart_rate_bpm,
                                   double pulse_velocity, double wall_force);

/// Organ motility, checked; throws core::ValidationError with the first error's pointer.
core::ActiveDeformation make_motility(const std::string& id, const std::string& target_object,
                                      const core::MotilitySpec& spec);

}  // namespace viscera::textures
