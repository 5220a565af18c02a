#include "core/scenario/vessel_paths.h"

#include <algorithm>
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

}  // namespace viscera::core
