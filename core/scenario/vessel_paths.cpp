#include "core/scenario/vessel_paths.h"

#include <algorithm>
#include <limits>
#include <string>

#include "core/error.h"

namespace viscera::core {

std::vector<std::vector<int>> vessel_root_paths(const VesselTree& tree) {
  const int n = static_cast<int>(tree.segments.size());
  for (int s = 0; s < n; ++s) {
    const int parent = tree.segments[static_cast<std::size_t>(s)].parent;
    if (parent < -1 || parent >= n || parent == s) {
      throw InputError("vessel tree \"" + tree.id + "\": segment " + std::to_string(s) +
                           " names parent " + std::to_string(parent) +
                           ", which is not a segment of the tree",
                       {"", "", tree.id});
    }
  }
  std::vector<std::vector<int>> paths(static_cast<std::size_t>(n));
  std::vector<char> known(static_cast<std::size_t>(n), 0);
  for (int s = 0; s < n; ++s) {
    // Walk up to a segment whose path is known (or past a root), then back down.
    std::vector<int> upward;
    int at = s;
    while (at >= 0 && !known[static_cast<std::size_t>(at)]) {
      if (static_cast<int>(upward.size()) > n) {
        throw InputError("vessel tree \"" + tree.id + "\": the parents of segment " +
                             std::to_string(s) + " form a cycle, so it has no root",
                         {"", "", tree.id});
      }
      upward.push_back(at);
      at = tree.segments[static_cast<std::size_t>(at)].parent;
    }
    for (auto it = upward.rbegin(); it != upward.rend(); ++it) {
      const int parent = tree.segments[static_cast<std::size_t>(*it)].parent;
      std::vector<int>& path = paths[static_cast<std::size_t>(*it)];
      if (parent >= 0) path = paths[static_cast<std::size_t>(parent)];
      path.push_back(*it);
      known[static_cast<std::size_t>(*it)] = 1;
    }
  }
  return paths;
}

std::vector<int> vessel_child_counts(const VesselTree& tree) {
  std::vector<int> children(tree.segments.size(), 0);
  for (const VesselSegment& segment : tree.segments) {
    if (segment.parent >= 0 && segment.parent < static_cast<int>(children.size()))
      ++children[static_cast<std::size_t>(segment.parent)];
  }
  return children;
}

VesselSegmentPoint nearest_point_on_segment(const VesselTree& tree, int segment,
                                            const Vec3& point) {
  if (segment < 0 || segment >= static_cast<int>(tree.segments.size()))
    throw UsageError("vessel tree \"" + tree.id + "\" has no segment " + std::to_string(segment));
  const VesselSegment& seg = tree.segments[static_cast<std::size_t>(segment)];
  const Vec3 axis = seg.distal - seg.proximal;
  const double length2 = axis.squaredNorm();
  VesselSegmentPoint at;
  at.segment = segment;
  at.projection = length2 > 0.0 ? (point - seg.proximal).dot(axis) / length2 : 0.0;
  at.along = std::clamp(at.projection, 0.0, 1.0);
  at.point = seg.proximal + at.along * axis;
  at.distance = (at.point - point).norm();
  at.wall_distance = at.distance - seg.radius;
  return at;
}

VesselSegmentPoint nearest_point_on_vessel(const VesselTree& tree, const Vec3& point) {
  VesselSegmentPoint best;
  best.distance = best.wall_distance = std::numeric_limits<double>::infinity();
  for (int s = 0; s < static_cast<int>(tree.segments.size()); ++s) {
    const VesselSegmentPoint at = nearest_point_on_segment(tree, s, point);
    if (at.wall_distance < best.wall_distance) best = at;
  }
  return best;
}

}  // namespace viscera::core
