#include "simulator/dynamics/tet_edge_groups.h"

#include <algorithm>

#include "core/mesh/counting_sort.h"

namespace viscera::sim {
namespace {

struct Entry {
  int lower, upper, tet;
};

}  // namespace

TetEdgeGroups tet_edge_groups(const std::vector<core::Tetrahedron>& tets, int node_count) {
  std::vector<Entry> entries, buffer;
  entries.reserve(6 * tets.size());
  for (int t = 0; t < static_cast<int>(tets.size()); ++t) {
    const auto& tet = tets[t];
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        entries.push_back({std::min(tet[a], tet[b]), std::max(tet[a], tet[b]), t});
  }
  // Radix sort, least significant key first: entries made in tet order end sorted by (lower,
  // upper, tet).
  core::stable_counting_pass(entries, buffer, node_count, [](const Entry& e) { return e.upper; });
  core::stable_counting_pass(entries, buffer, node_count, [](const Entry& e) { return e.lower; });
  TetEdgeGroups groups;
  groups.tets.reserve(entries.size());
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const Entry& e = entries[i];
    if (i == 0 || e.lower != entries[i - 1].lower || e.upper != entries[i - 1].upper) {
      groups.edges.push_back({e.lower, e.upper});
      groups.first.push_back(static_cast<int>(groups.tets.size()));
    }
    groups.tets.push_back(e.tet);
  }
  groups.first.push_back(static_cast<int>(groups.tets.size()));
  return groups;
}

}  // namespace viscera::sim
