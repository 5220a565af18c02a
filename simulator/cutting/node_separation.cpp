#include "simulator/cutting/node_separation.h"

#include <algorithm>
#include <numeric>

#include "core/mesh/counting_sort.h"

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
  const int lo = std::min({a, b, c}), hi = std::max({a, b, c});
  return FaceKey{{lo, std::max(std::min(a, b), std::min(std::max(a, b), c)), hi}};
}

// Sorts faces keyed by (lowest node << 32 | middle node, highest node): a radix sort, one
// counting pass on the middle node and one on the lowest, then a sort of each run of faces
// sharing both (a handful). Linear in the faces and nodes where a comparison sort is not.
template <typename Face>
void sort_by_lowest_node(std::vector<Face>& faces, int node_count) {
  std::vector<Face> buffer;
  core::stable_counting_pass(faces, buffer, node_count,
                             [](const Face& f) { return static_cast<int>(f.ab & 0xffffffffu); });
  core::stable_counting_pass(faces, buffer, node_count,
                             [](const Face& f) { return static_cast<int>(f.ab >> 32); });
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].ab == faces[i].ab)
      ++j;
    if (j - i > 1) std::sort(faces.begin() + i, faces.begin() + j);
    i = j;
  }
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
  std::vector<int> slot_of(w.tets.size(), -1);
  for (int v = 0; v < first_new; ++v) {
    if (!w.on_cut[v]) continue;
    for (int k = w.star_offset[v]; k < w.star_offset[v + 1]; ++k)
      slot_of[w.star_tets[k]] = 0;
  }
  for (int t = 0; t < static_cast<int>(w.tets.size()); ++t) {
    if (slot_of[t] < 0) continue;
    slot_of[t] = static_cast<int>(result.affected.size());
    result.affected.push_back(t);
    result.conforming.push_back(w.tets[t]);
  }
  result.neighbour = face_neighbours(result.conforming, w.on_cut);
  std::vector<int> up, local_of(w.tets.size(), -1), copy_of_root;
  for (int v = 0; v < first_new; ++v) {
    if (!w.on_cut[v]) continue;
    const int begin = w.star_offset[v], end = w.star_offset[v + 1];
    const int size = end - begin;
    up.resize(size);
    std::iota(up.begin(), up.end(), 0);
    for (int i = 0; i < size; ++i)
      local_of[w.star_tets[begin + i]] = i;
    // Tets of the star stay together across each face through v that is not a cut face.
    for (int i = 0; i < size; ++i) {
      const int t = w.star_tets[begin + i];
      const int slot = slot_of[t];
      const Tetrahedron& c = result.conforming[slot];
      for (int f = 0; f < 4; ++f) {
        if (c[f] == v) continue;  // face f is opposite corner f
        const int across = result.neighbour[4 * slot + f];
        if (across < 0) continue;
        const int u = result.affected[across / 4];
        const auto& k = kFaces[f];
        const bool cut_face = w.on_cut[c[k[0]]] && w.on_cut[c[k[1]]] && w.on_cut[c[k[2]]] &&
                              tet_side[t] * tet_side[u] == -1;
        if (!cut_face) up[find(up, i)] = find(up, local_of[u]);
      }
    }
    // The group of the lowest tet keeps v; every other group gets a copy.
    copy_of_root.assign(size, -1);
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

std::vector<int> face_neighbours(const std::vector<Tetrahedron>& tets,
                                 const std::vector<std::uint8_t>& on_cut) {
  struct Face {
    std::uint64_t ab;
    int c;
    int slot;  // 4 · tet + face
    bool operator<(const Face& o) const { return ab < o.ab || (ab == o.ab && c < o.c); }
    bool same(const Face& o) const { return ab == o.ab && c == o.c; }
  };
  std::vector<Face> faces;
  faces.reserve(4 * tets.size());
  int node_count = 0;
  for (std::size_t i = 0; i < tets.size(); ++i) {
    const Tetrahedron& t = tets[i];
    for (int f = 0; f < 4; ++f) {
      const auto& k = kFaces[f];
      if (!(on_cut[t[k[0]]] || on_cut[t[k[1]]] || on_cut[t[k[2]]])) continue;
      const FaceKey key = key_of(t[k[0]], t[k[1]], t[k[2]]);
      faces.push_back(
          {(static_cast<std::uint64_t>(key.n[0]) << 32) | static_cast<std::uint32_t>(key.n[1]),
           key.n[2], static_cast<int>(4 * i + f)});
      node_count = std::max(node_count, key.n[2] + 1);
    }
  }
  sort_by_lowest_node(faces, node_count);
  std::vector<int> neighbour(4 * tets.size(), -1);
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].same(faces[i]))
      ++j;
    if (j - i == 2) {
      neighbour[faces[i].slot] = faces[i + 1].slot;
      neighbour[faces[i + 1].slot] = faces[i].slot;
    }
    i = j;
  }
  return neighbour;
}

std::vector<Triangle> rebuild_surface(const std::vector<Triangle>& old_surface,
                                      const std::vector<Tetrahedron>& old_tets, const CutWork& w,
                                      const SeparationResult& separation,
                                      std::vector<int>& cut_faces,
                                      std::vector<int>& cut_face_tets) {
  // The old surface faces of the tets the cut affects are replaced by their new versions. Only
  // faces with all three nodes on the old surface can be such faces.
  std::vector<std::uint8_t> on_surface(w.on_cut.size(), 0);
  for (const Triangle& f : old_surface) {
    for (int v : f)
      on_surface[v] = 1;
  }
  std::vector<std::uint8_t> parent_affected(old_tets.size(), 0);
  std::vector<std::array<int, 3>> parent_faces;
  for (int t : separation.affected) {
    const int p = w.parent[t];
    if (parent_affected[p]) continue;
    parent_affected[p] = 1;
    const Tetrahedron& o = old_tets[p];
    for (const auto& f : kFaces) {
      if (on_surface[o[f[0]]] && on_surface[o[f[1]]] && on_surface[o[f[2]]]) {
        parent_faces.push_back(key_of(o[f[0]], o[f[1]], o[f[2]]).n);
      }
    }
  }
  std::sort(parent_faces.begin(), parent_faces.end());
  // Nodes of the affected parents' surface faces: a face without one of them stays.
  std::vector<std::uint8_t> near_cut(on_surface.size(), 0);
  for (const auto& f : parent_faces) {
    for (int v : f)
      near_cut[v] = 1;
  }
  std::vector<Triangle> surface;
  surface.reserve(old_surface.size() + 4 * separation.affected.size());
  std::vector<std::array<int, 3>> removed;
  for (const Triangle& f : old_surface) {
    if (!(near_cut[f[0]] && near_cut[f[1]] && near_cut[f[2]])) {
      surface.push_back(f);
      continue;
    }
    const auto k = key_of(f[0], f[1], f[2]).n;
    if (std::binary_search(parent_faces.begin(), parent_faces.end(), k)) {
      removed.push_back(k);
    } else {
      surface.push_back(f);
    }
  }
  std::sort(removed.begin(), removed.end());
  // Boundary faces of the affected tets after separation. A face with a node on the cut had
  // its neighbour found before separation: it is on the boundary when it had none (old
  // surface) or when separation gave the two tets different copies of one of its nodes; a cut
  // face had a neighbour before. Faces without nodes on the cut keep their ids: they are on
  // the boundary exactly when they were old surface.
  const std::size_t count = separation.affected.size();
  std::vector<std::uint8_t> shared_before(4 * count, 0), boundary_after(4 * count, 0);
  for (std::size_t i = 0; i < count; ++i) {
    const Tetrahedron& c = separation.conforming[i];
    const Tetrahedron& t = w.tets[separation.affected[i]];
    for (int f = 0; f < 4; ++f) {
      const auto& k = kFaces[f];
      const int slot = static_cast<int>(4 * i + f);
      const int cut_nodes = w.on_cut[c[k[0]]] + w.on_cut[c[k[1]]] + w.on_cut[c[k[2]]];
      if (cut_nodes == 0) {
        boundary_after[slot] =
            std::binary_search(removed.begin(), removed.end(), key_of(c[k[0]], c[k[1]], c[k[2]]).n);
        continue;
      }
      const int across = separation.neighbour[slot];
      if (across < 0) {
        boundary_after[slot] = 1;
        continue;
      }
      shared_before[slot] = cut_nodes == 3;
      const Tetrahedron& u = w.tets[separation.affected[across / 4]];
      const auto& m = kFaces[across % 4];
      boundary_after[slot] =
          !(key_of(t[k[0]], t[k[1]], t[k[2]]) == key_of(u[m[0]], u[m[1]], u[m[2]]));
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
