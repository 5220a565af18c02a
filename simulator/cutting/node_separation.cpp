#include "simulator/cutting/node_separation.h"

#include <algorithm>
#include <numeric>

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
  // Copies map back to the node they were made from, so face keys use the conforming ids.
  std::vector<int> original;
  const auto conforming_id = [&](int u) { return u < first_new ? u : original[u - first_new]; };
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
      const Tetrahedron& t = w.tets[w.star_tets[begin + i]];
      int others[3], count = 0;
      for (int u : t) {
        if (u != v) others[count++] = conforming_id(u);
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
        original.push_back(v);
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
                                      std::vector<int>& cut_faces,
                                      std::vector<int>& cut_face_tets) {
  // The old surface faces of the tets the cut affects are replaced by their new versions.
  std::vector<std::uint8_t> parent_affected(old_tets.size(), 0);
  std::vector<std::array<int, 3>> parent_faces;
  for (int t : separation.affected) {
    const int p = w.parent[t];
    if (parent_affected[p]) continue;
    parent_affected[p] = 1;
    const Tetrahedron& o = old_tets[p];
    for (const auto& f : kFaces)
      parent_faces.push_back(key_of(o[f[0]], o[f[1]], o[f[2]]).n);
  }
  std::sort(parent_faces.begin(), parent_faces.end());
  std::vector<Triangle> surface;
  std::vector<std::array<int, 3>> removed;
  for (const Triangle& f : old_surface) {
    const auto k = key_of(f[0], f[1], f[2]).n;
    if (std::binary_search(parent_faces.begin(), parent_faces.end(), k)) {
      removed.push_back(k);
    } else {
      surface.push_back(f);
    }
  }
  std::sort(removed.begin(), removed.end());
  // Boundary faces of the affected tets after separation: a face seen once among them. Faces
  // without a node on the cut keep their ids, so only faces with one take part in the sort;
  // those with all three nodes on the cut are also compared before separation (cut faces).
  struct Face {
    std::uint64_t ab;
    int c;
    int slot;  // 4 · (index in affected) + face
    bool operator<(const Face& o) const { return ab < o.ab || (ab == o.ab && c < o.c); }
    bool same(const Face& o) const { return ab == o.ab && c == o.c; }
  };
  const auto face_of = [](int x, int y, int z, int slot) {
    const FaceKey k = key_of(x, y, z);
    return Face{(static_cast<std::uint64_t>(k.n[0]) << 32) | static_cast<std::uint32_t>(k.n[1]),
                k.n[2], slot};
  };
  const std::size_t count = separation.affected.size();
  std::vector<Face> before, after;
  after.reserve(4 * count);
  for (std::size_t i = 0; i < count; ++i) {
    const Tetrahedron& c = separation.conforming[i];
    const Tetrahedron& t = w.tets[separation.affected[i]];
    for (int f = 0; f < 4; ++f) {
      const auto& k = kFaces[f];
      const int cut_nodes = w.on_cut[c[k[0]]] + w.on_cut[c[k[1]]] + w.on_cut[c[k[2]]];
      if (cut_nodes == 0) continue;
      const int slot = static_cast<int>(4 * i + f);
      after.push_back(face_of(t[k[0]], t[k[1]], t[k[2]], slot));
      if (cut_nodes == 3) before.push_back(face_of(c[k[0]], c[k[1]], c[k[2]], slot));
    }
  }
  std::sort(before.begin(), before.end());
  std::sort(after.begin(), after.end());
  std::vector<std::uint8_t> shared_before(4 * count, 0), boundary_after(4 * count, 0);
  for (std::size_t i = 0; i + 1 < before.size(); ++i) {
    if (before[i].same(before[i + 1]))
      shared_before[before[i].slot] = shared_before[before[i + 1].slot] = 1;
  }
  for (std::size_t i = 0; i < after.size();) {
    std::size_t j = i + 1;
    while (j < after.size() && after[j].same(after[i]))
      ++j;
    if (j - i == 1) boundary_after[after[i].slot] = 1;
    i = j;
  }
  // Faces without nodes on the cut are on the boundary exactly when they were old surface.
  for (std::size_t i = 0; i < count; ++i) {
    const Tetrahedron& c = separation.conforming[i];
    for (int f = 0; f < 4; ++f) {
      const auto& k = kFaces[f];
      if (w.on_cut[c[k[0]]] || w.on_cut[c[k[1]]] || w.on_cut[c[k[2]]]) continue;
      boundary_after[4 * i + f] =
          std::binary_search(removed.begin(), removed.end(), key_of(c[k[0]], c[k[1]], c[k[2]]).n);
    }
  }
  for (std::size_t i = 0; i < count; ++i) {
    const Tetrahedron& t = w.tets[separation.affected[i]];
    for (int f = 0; f < 4; ++f) {
      if (!boundary_after[4 * i + f]) continue;
      const auto& k = kFaces[f];
      if (shared_before[4 * i + f]) {
        cut_faces.push_back(static_cast<int>(surface.size()));
        cut_face_tets.push_back(separation.affected[i]);
      }
      surface.push_back({t[k[0]], t[k[1]], t[k[2]]});
    }
  }
  return surface;
}

}  // namespace viscera::sim::cutting
