#pragma once
/// Vessel trees as the JSON that `viscera vessels` writes: the scenario's VesselTree fields plus
/// the derived children, lengths and a summary, so a reader needs no tree code to use it.
///
///     {"format": "viscera-vessel-tree", "version": 1, "units": {...},
///      "tree": {"id", "host_object", "kind", "segments": [{"id", "parent", "children",
///               "proximal", "distal", "radius", "length", "flow"}, …]},
///      "summary": {"segments", "terminals", "volume", "murray_max_deviation", "intersections"}}

#include <nlohmann/json.hpp>
#include <string>

#include "core/scenario/scenario_parts.h"

namespace viscera::templates {

/// The document above.
nlohmann::json vessel_tree_to_json(const core::VesselTree& tree);

/// Reads the "tree" member back (children, lengths and summary are derived, so they are not
/// read). Throws core::ValidationError naming `file` and the JSON pointer.
core::VesselTree vessel_tree_from_json(const nlohmann::json& json, const std::string& file);

}  // namespace viscera::templates
