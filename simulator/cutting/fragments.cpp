#include "simulator/cutting/fragments.h"

#include <algorithm>
#include <numeric>
#include <string>

#include "core/error.h"

namespace viscera::sim::cutting {
namespace {

int find(std::vector<int>& up, int i) {
  while (up[i] != i)
    i = up[i] = up[up[i]];
  return i;
}

}  // namespace

std::vector<Fragment> body_fragments(const core::TetMesh& mesh,
                                     const std::vector<std::uint8_t>& anchored) {
  const int n = static_cast<int>(mesh.nodes.size());
  const std::vector<std::uint8_t>& anchor = anchored.empty() ? mesh.fixed : anchored;
  if (!anchor.empty() && static_cast<int>(anchor.size()) != n) {
    throw core::InputError("the anchor flags have " + std::to_string(anchor.size()) +
                           " entries for a body of " + std::to_string(n) + " nodes");
  }
  std::vector<int> up(n);
  std::iota(up.begin(), up.end(), 0);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    for (int v : mesh.tets[t]) {
      if (v < 0 || v >= n) {
        throw core::InputError("tet " + std::to_string(t) + " names node " + std::to_string(v) +
                               ", which the body does not have");
      }
    }
    const int root = find(up, mesh.tets[t][0]);
    for (int k = 1; k < 4; ++k)
      up[find(up, mesh.tets[t][k])] = root;
  }
  std::vector<int> index_of_root(n, -1);
  std::vector<Fragment> fragments;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const int root = find(up, mesh.tets[t][0]);
    if (index_of_root[root] < 0) {
      index_of_root[root] = static_cast<int>(fragments.size());
      fragments.emplace_back();
    }
    Fragment& f = fragments[index_of_root[root]];
    f.tets.push_back(static_cast<int>(t));
    const auto& q = mesh.tets[t];
    f.rest_volume +=
        core::signed_volume(mesh.nodes[q[0]], mesh.nodes[q[1]], mesh.nodes[q[2]], mesh.nodes[q[3]]);
  }
  for (int v = 0; v < n; ++v) {
    const int root = find(up, v);
    if (index_of_root[root] < 0) continue;  // a node of no tet
    Fragment& f = fragments[index_of_root[root]];
    f.nodes.push_back(v);
    if (!anchor.empty() && anchor[v]) f.anchored = true;
  }
  return fragments;
}

std::vector<Fragment> excised_chips(const core::TetMesh& mesh,
                                    const std::vector<std::uint8_t>& anchored) {
  std::vector<Fragment> chips;
  for (Fragment& f : body_fragments(mesh, anchored)) {
    if (!f.anchored) chips.push_back(std::move(f));
  }
  return chips;
}

core::TetMesh fragment_mesh(const core::TetMesh& mesh, const Fragment& fragment,
                            std::vector<int>* node_map) {
  std::vector<int> new_index(mesh.nodes.size(), -1);
  core::TetMesh out;
  for (int v : fragment.nodes) {
    new_index[v] = static_cast<int>(out.nodes.size());
    out.nodes.push_back(mesh.nodes[v]);
    if (!mesh.node_mass.empty()) out.node_mass.push_back(mesh.node_mass[v]);
    if (!mesh.fixed.empty()) out.fixed.push_back(mesh.fixed[v]);
  }
  for (int t : fragment.tets) {
    const auto& q = mesh.tets[t];
    out.tets.push_back({new_index[q[0]], new_index[q[1]], new_index[q[2]], new_index[q[3]]});
    if (!mesh.tet_labels.empty()) out.tet_labels.push_back(mesh.tet_labels[t]);
  }
  for (const auto& f : mesh.surface_faces) {
    if (new_index[f[0]] >= 0 && new_index[f[1]] >= 0 && new_index[f[2]] >= 0) {
      out.surface_faces.push_back({new_index[f[0]], new_index[f[1]], new_index[f[2]]});
    }
  }
  if (node_map) *node_map = fragment.nodes;
  return out;
}

}  // namespace viscera::sim::cutting
