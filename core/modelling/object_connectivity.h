#pragma once
/// Object connectivity (seed 001 §3.3: "Organ models are connected with each other at their mass
/// knots with a nearest-neighbour approach and form organ model groups, which can be combined to
/// create the final surgical simulation scene"). Knots are the nodes of an object's simulation
/// body; connections are stored in the Scenario as pairs of body nodes.

#include <array>
#include <map>
#include <string>
#include <vector>

#include "core/scenario/scenario.h"

namespace viscera::core {

/// Pairs (i in a, j in b) of knots closer than `within` m where j is the nearest knot of b to
/// i, or i the nearest knot of a to j (so neither object's spacing decides alone), sorted and
/// unique. Ties go to the lower index. Throws UsageError for a non-positive distance.
std::vector<std::array<int, 2>> nearest_knot_pairs(const std::vector<Vec3>& a,
                                                   const std::vector<Vec3>& b, double within);

/// A connection between two objects of a scenario at their nearest body knots within `within`
/// m, each pair a spring of `stiffness` N/m. Throws UsageError when an object is missing, has
/// no body, or is connected to itself; the result may have no pairs (the caller decides whether
/// that is an error).
Connection connect_objects(const Scenario& scenario, const std::string& object_a,
                           const std::string& object_b, double within, double stiffness = 100.0);

/// Puts the objects into organ group `group` (SceneObject::group). Throws UsageError naming an
/// unknown object.
void assign_organ_group(Scenario& scenario, const std::string& group,
                        const std::vector<std::string>& object_ids);

/// Organ groups of a scenario: group name → object ids in scenario order (ungrouped left out).
std::map<std::string, std::vector<std::string>> organ_groups(const Scenario& scenario);

}  // namespace viscera::core
