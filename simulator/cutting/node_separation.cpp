#include "simulator/cutting/node_separation.h"

#include <algorithm>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

namespace viscera::sim::cutting {
namespace {

using core::Tetrahedron;
using core::Triangle;

// Faces of a positively oriented tet (a,b,c,d), counter-clockwise seen from outside.
constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

struct FaceKey {
  std::array<int, 3> n;
  bool operator==(const FaceKey&) const = default;
};
struct FaceHash {
  std::size_t operator()(const FaceKey& k) const {
    std::uint64_t h = static_cast<std::uint32_t>(k.n[0]);
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(k.n[1]);
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(k.n[2]);
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

FaceKey key_of(int a, int b, int c) {
  FaceKey k{{a, b, c}};
  std::sort(k.n.begin(), k.n.end());
  return k;
}

int find(std::vector<int>& up, int i) {
  while (up[i] != i)
    i = up[i] = up[up[i]];
  return i;
}

}  // namespace

void build_stars(CutWork& w) {
  const std::size_t n = w.rest.size();
  w.star_offset.assign(n + 1, 0);
  for (const Tetrahedron& t : w.tets) {
    for (int v : t)
      ++w.star_offset[v + 1];
  }
  std::partial_sum(w.star_offset.begin(), w.star_offset.end(), w.star_offset.begin());
  w.star_tets.assign(w.star_offset.back(), 0);
  std::vector<int> fill(w.star_offset.begin(), w.star_offset.end() - 1);
  for (int t = 0; t < static_cast<int>(w.tets.size()); ++t) {
    for (int v : w.tets[t])
      w.star_tets[fill[v]++] = t;
  }
}

SeparationResult separate_cut_nodes(CutWork& w, const std::vector<std::int8_t>& tet_side) {
  SeparationResult result;
  const int first_new = static_cast<int>(w.rest.size());
  std::vector<std::uint8_t> in_affected(w.tets.size(), 0);
  for (int v = 0; v < first_new; ++v) {
    if (!w.on_cut[v]) continue;
    for (int k = w.star_offset[v]; k < w.star_offset[v + 1]; ++k) {
      in_affected[w.star_tets[k]] = 1;
    }
  }
  for (int t = 0; t < static_cast<int>(w.tets.size()); ++t) {
    if (in_affected[t]) result.affected.push_back(t);
  }
  for (int t : result.affected)
    result.conforming.push_back(w.tets[t]);
  const std::vector<Tetrahedron> conforming_all = w.tets;  // ids before any duplication
  struct Entry {
    std::uint64_t key;
    int local;
    bool operator<(const Entry& o) const {
      return key < o.key || (key == o.key && local < o.local);
    }
  };
  std::vector<Entry> entries;
  std::vector<int> up;
  for (int v = 0; v < first_new; ++v) {
    if (!w.on_cut[v]) continue;
    const int begin = w.star_offset[v], end = w.star_offset[v + 1];
    const int size = end - begin;
    entries.clear();
    for (int i = 0; i < size; ++i) {
      const Tetrahedron& t = conforming_all[w.star_tets[begin + i]];
      int others[3], count = 0;
      for (int u : t) {
        if (u != v) others[count++] = u;
      }
      // The three faces through v: v with each pair of the other corners.
      for (int a = 0; a < 3; ++a) {
        for (int b = a + 1; b < 3; ++b) {
          const auto lo = static_cast<std::uint64_t>(std::min(others[a], others[b]));
          const auto hi = static_cast<std::uint64_t>(std::max(others[a], others[b]));
          entries.push_back({(lo << 32) | hi, i});
        }
      }
    }
    std::sort(entries.begin(), entries.end());
    up.resize(size);
    std::iota(up.begin(), up.end(), 0);
    for (std::size_t e = 0; e + 1 < entries.size(); ++e) {
      if (entries[e].key != entries[e + 1].key) continue;
      const int ta = w.star_tets[begin + entries[e].local];
      const int tb = w.star_tets[begin + entries[e + 1].local];
      const int x = static_cast<int>(entries[e].key >> 32);
      const int y = static_cast<int>(entries[e].key & 0xffffffffu);
      const bool cut_face = w.on_cut[x] && w.on_cut[y] && tet_side[ta] * tet_side[tb] == -1;
      if (!cut_face) up[find(up, entries[e].local)] = find(up, entries[e + 1].local);
    }
    // The group of the lowest tet keeps v; every other group gets a copy.
    std::vector<int> copy_of_root(size, -1);
    const int keeper = find(up, 0);
    for (int i = 0; i < size; ++i) {
      const int root = find(up, i);
      if (root == keeper) continue;
      if (copy_of_root[root] < 0) {
        copy_of_root[root] = static_cast<int>(w.rest.size());
        w.rest.push_back(w.rest[v]);
        w.current.push_back(w.current[v]);
        // A copy has the sources of its original (an old node is its own source).
        w.origin.push_back(w.origin[v].empty() ? std::vector<NodeSource>{{v, 1.0}} : w.origin[v]);
        w.on_cut.push_back(1);
        ++result.duplicated;
      }
      for (int& u : w.tets[w.star_tets[begin + i]]) {
        if (u == v) u = copy_of_root[root];
      }
    }
  }
  return result;
}

std::vector<Triangle> rebuild_surface(const std::vector<Triangle>& old_surface,
                                      const std::vector<Tetrahedron>& old_tets, const CutWork& w,
                                      const SeparationResult& separation,
                                      std::vector<int>& cut_faces) {
  // The old surface faces of the tets the cut affects are replaced by their new versions.
  std::vector<std::uint8_t> parent_affected(old_tets.size(), 0);
  std::unordered_set<FaceKey, FaceHash> parent_faces;
  for (int t : separation.affected) {
    const int p = w.parent[t];
    if (parent_affected[p]) continue;
    parent_affected[p] = 1;
    const Tetrahedron& o = old_tets[p];
    for (const auto& f : kFaces)
      parent_faces.insert(key_of(o[f[0]], o[f[1]], o[f[2]]));
  }
  std::vector<Triangle> surface;
  std::unordered_set<FaceKey, FaceHash> removed;
  for (const Triangle& f : old_surface) {
    const FaceKey k = key_of(f[0], f[1], f[2]);
    if (parent_faces.count(k)) {
      removed.insert(k);
    } else {
      surface.push_back(f);
    }
  }
  // Boundary faces of the affected tets, before and after separation.
  std::unordered_map<FaceKey, int, FaceHash> before, after;
  before.reserve(separation.affected.size() * 4);
  after.reserve(separation.affected.size() * 4);
  for (std::size_t i = 0; i < separation.affected.size(); ++i) {
    const Tetrahedron& c = separation.conforming[i];
    const Tetrahedron& t = w.tets[separation.affected[i]];
    for (const auto& f : kFaces) {
      ++before[key_of(c[f[0]], c[f[1]], c[f[2]])];
      ++after[key_of(t[f[0]], t[f[1]], t[f[2]])];
    }
  }
  for (std::size_t i = 0; i < separation.affected.size(); ++i) {
    const Tetrahedron& c = separation.conforming[i];
    const Tetrahedron& t = w.tets[separation.affected[i]];
    for (const auto& f : kFaces) {
      if (after[key_of(t[f[0]], t[f[1]], t[f[2]])] != 1) continue;
      const FaceKey old_key = key_of(c[f[0]], c[f[1]], c[f[2]]);
      const bool on_cut_nodes = w.on_cut[c[f[0]]] || w.on_cut[c[f[1]]] || w.on_cut[c[f[2]]];
      const bool was_inside = before[old_key] == 2;
      if (!on_cut_nodes && !removed.count(old_key)) continue;  // shared with an untouched tet
      if (was_inside) cut_faces.push_back(static_cast<int>(surface.size()));
      surface.push_back({t[f[0]], t[f[1]], t[f[2]]});
    }
  }
  return surface;
}

}  // namespace viscera::sim::cutting
