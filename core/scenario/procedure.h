#pragma once
/// Procedures as data (seed 000 §11): the hierarchical decomposition of a surgery into steps,
/// substeps and tasks, with the instrument it is trained with and its limits. The shipped
/// definitions live in data/procedures/*.json and are compiled in; templates embed one in the
/// scenarios they build with apply_procedure(scenario.session, procedure_definition(name)).
///
/// Task kinds the simulator detects from tool and camera state (parameters in SI units, angles
/// in degrees; a target is a "landmark" id of the scenario or an explicit "position" [x, y, z]
/// with an optional "normal"):
///   reach            tip within "radius" of the target
///   centre-target    target within "max_angle" of the view axis, visible, at a distance in
///                    ["min_distance", "max_distance"], for "hold_time" s
///   inspect-surface  "fraction" of the area of "object"'s surface seen by the camera, counting
///                    only vertices whose "region_attribute" equals "region_value" when given
///   withdraw         tip back out past the plane through the target (normal pointing out) by
///                    "margin", after having been inside
///   touch            tool in contact ("object" optional) with a force in ["min_force",
///                    "max_force"] N for "hold_time" s
///   settle           kinetic energy below "kinetic_energy_below" J for "hold_time" s
/// Any task may name the "tool" it needs; tasks whose tool or kind the runtime cannot simulate
/// (grasp, clip, cut, pull) are reported unavailable with the reason, never passed.

#include <string>
#include <vector>

#include "core/scenario/scenario_parts.h"

namespace viscera::core {

/// One procedure: what the trainee does, with which instrument, within which limits.
struct ProcedureDefinition {
  std::string name;       ///< e.g. "diagnostic-hysteroscopy"
  std::string title;      ///< e.g. "Diagnostic hysteroscopy"
  std::string procedure;  ///< the Scenario::procedure it belongs to (kProcedures)
  std::string description;
  InstrumentSpec instrument;
  double duration_limit = 600.0;   ///< s
  double force_warning = 0.0;      ///< N, 0: none
  double perforation_depth = 0.0;  ///< m, 0: the local wall thickness
  std::vector<StepSpec> steps;

  bool operator==(const ProcedureDefinition&) const = default;
};

/// Names of the shipped procedure definitions, sorted.
std::vector<std::string> procedure_definition_names();

/// The shipped procedure `name`; throws UsageError listing the known names when there is none.
const ProcedureDefinition& procedure_definition(const std::string& name);

/// Parses a procedure document ({"format": "viscera-procedure", "version": 1, …}); throws
/// ValidationError naming `file` and the JSON pointer of the bad member (duplicate ids, a step
/// without tasks, a negative limit, …).
ProcedureDefinition procedure_from_json(const nlohmann::json& json, const std::string& file);
nlohmann::json procedure_to_json(const ProcedureDefinition& procedure);

/// Puts `procedure` into a scenario's session: steps, instrument, limits and its name.
void apply_procedure(SessionSpec& session, const ProcedureDefinition& procedure);

/// Every task of `session`: the loose tasks first, then those of the steps in order.
std::vector<const TaskSpec*> all_tasks(const SessionSpec& session);

}  // namespace viscera::core
