#pragma once
/// Paths through an authored vessel tree: for every segment, the segments from the top of its
/// hierarchy (a segment whose parent is −1) down to it. Pulse waves run along these paths (seed
/// 001 §5.1.1), bleeding reaches a cut through them, and a clip on one of them stops both. Also
/// where a point (a clip, a cut face) lies against the tree's segments.

#include <vector>

#include "core/scenario/scenario_parts.h"

namespace viscera::core {

/// Per segment of `tree`, its root path: segment indices from the root to the segment itself,
/// both included. Throws InputError naming the tree and the segment for a parent index out of
/// range (or the segment itself), or for parents that form a cycle.
std::vector<std::vector<int>> vessel_root_paths(const VesselTree& tree);

/// Per segment, how many segments hang from it directly.
std::vector<int> vessel_child_counts(const VesselTree& tree);

/// Where a point lies against one segment of a vessel tree: the point of the segment's axis
/// (proximal to distal end) nearest it, and how far it is from the axis and from the wall.
struct VesselSegmentPoint {
  int segment = -1;            ///< index into the tree's segments, −1 for none
  double along = 0.0;          ///< where `point` lies: 0 at the proximal end, 1 at the distal
  double projection = 0.0;     ///< the same for the given point's foot on the axis line, not
                               ///< clamped: below 0 or above 1 beyond an end
  Vec3 point = Vec3::Zero();   ///< m, the axis point nearest the given point
  double distance = 0.0;       ///< m, from the given point to `point`
  double wall_distance = 0.0;  ///< m, distance minus the segment's radius (< 0 inside the lumen)
};

/// The point of the axis of segment `segment` of `tree` nearest `point` (m, in the frame the tree
/// was authored in: its host's rest frame). A segment of zero length answers with its proximal
/// end (along and projection 0). Throws UsageError for a segment index not in the tree.
VesselSegmentPoint nearest_point_on_segment(const VesselTree& tree, int segment, const Vec3& point);

/// Over every segment of `tree`, nearest_point_on_segment() of the segment whose wall lies
/// nearest `point` (smallest wall_distance; the first in segment order on a tie). A tree without
/// segments gives segment −1 with infinite distances.
VesselSegmentPoint nearest_point_on_vessel(const VesselTree& tree, const Vec3& point);

}  // namespace viscera::core
