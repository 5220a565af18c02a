#pragma once
/// Paths through an authored vessel tree: for every segment, the segments from the top of its
/// hierarchy (a segment whose parent is −1) down to it. Pulse waves run along these paths (seed
/// 001 §5.1.1), bleeding reaches a cut through them, and a clip on one of them stops both.

#include <vector>

#include "core/scenario/scenario_parts.h"

namespace viscera::core {

/// Per segment of `tree`, its root path: segment indices from the root to the segment itself,
/// both included. Throws InputError naming the tree and the segment for a parent index out of
/// range (or the segment itself), or for parents that form a cycle.
std::vector<std::vector<int>> vessel_root_paths(const VesselTree& tree);

/// Per segment, how many segments hang from it directly.
std::vector<int> vessel_child_counts(const VesselTree& tree);

}  // namespace viscera::core
