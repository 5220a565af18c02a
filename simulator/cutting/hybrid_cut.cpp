#include "simulator/cutting/hybrid_cut.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "core/mesh/surface_embedding.h"
#include "simulator/cutting/cut_classification.h"
#include "simulator/cutting/node_separation.h"
#include "simulator/cutting/visual_surface_cut.h"

namespace viscera::sim::cutting {
namespace {

using core::InputError;
using core::Tetrahedron;
using core::Vec3;

void check_input(const core::TetMesh& body, const std::vector<Vec3>& current, const CutSurface& cut,
                 const HybridCutOptions& options) {
  if (body.tets.empty()) throw InputError("the body to cut has no tetrahedra");
  if (current.size() != body.nodes.size()) {
    throw InputError("the body to cut has " + std::to_string(body.nodes.size()) + " nodes but " +
                     std::to_string(current.size()) + " current positions");
  }
  for (std::size_t i = 0; i < current.size(); ++i) {
    if (!current[i].allFinite() || !body.nodes[i].allFinite()) {
      throw InputError("node " + std::to_string(i) +
                       " of the body to cut has a non-finite position");
    }
  }
  if (cut.triangles.empty()) throw InputError("the cut surface has no triangles");
  for (std::size_t i = 0; i < cut.vertices.size(); ++i) {
    if (!cut.vertices[i].allFinite()) {
      throw InputError("vertex " + std::to_string(i) + " of the cut surface is not finite");
    }
  }
  for (std::size_t t = 0; t < cut.triangles.size(); ++t) {
    for (int v : cut.triangles[t]) {
      if (v < 0 || v >= static_cast<int>(cut.vertices.size())) {
        throw InputError("triangle " + std::to_string(t) + " of the cut surface names vertex " +
                         std::to_string(v) + ", which does not exist");
      }
    }
  }
  if (!(options.snap_fraction >= 0.0 && options.snap_fraction < 0.5)) {
    throw InputError("the snapping fraction must lie in [0, 0.5), not " +
                     std::to_string(options.snap_fraction));
  }
  if (!(options.min_dihedral_degrees >= 0.0 && options.min_dihedral_degrees < 30.0)) {
    throw InputError("the smallest dihedral angle bound must lie in [0°, 30°)");
  }
}

double mean_cut_edge(const CutSurface& cut) {
  double sum = 0.0;
  for (const auto& t : cut.triangles) {
    sum += (cut.vertices[t[0]] - cut.vertices[t[1]]).norm() +
           (cut.vertices[t[1]] - cut.vertices[t[2]]).norm() +
           (cut.vertices[t[2]] - cut.vertices[t[0]]).norm();
  }
  return sum / (3.0 * cut.triangles.size());
}

double volume_of(const std::vector<Tetrahedron>& tets, const std::vector<Vec3>& x) {
  double v = 0.0;
  for (const auto& t : tets)
    v += core::signed_volume(x[t[0]], x[t[1]], x[t[2]], x[t[3]]);
  return v;
}

TopologyChange unchanged(const core::TetMesh& body, const std::vector<Vec3>& current) {
  TopologyChange change;
  change.mesh = body;
  change.current = current;
  const int n = static_cast<int>(body.nodes.size());
  change.node_source_offset.resize(n + 1);
  for (int i = 0; i <= n; ++i)
    change.node_source_offset[i] = i;
  change.node_source.reserve(n);
  for (int i = 0; i < n; ++i)
    change.node_source.push_back({i, 1.0});
  change.tet_parent.resize(body.tets.size());
  for (std::size_t t = 0; t < body.tets.size(); ++t)
    change.tet_parent[t] = static_cast<int>(t);
  change.on_cut.assign(n, 0);
  change.statistics.tets_before = change.statistics.tets_after = body.tets.size();
  change.statistics.rest_volume_before = change.statistics.rest_volume_after =
      volume_of(body.tets, body.nodes);
  change.statistics.current_volume_before = change.statistics.current_volume_after =
      volume_of(body.tets, current);
  return change;
}

// Decomposes the traversed tets; returns the indices of the new tets (children).
std::vector<int> decompose_traversed(const core::TetMesh& body, const CutClassification& c,
                                     CutWork& w, double& min_dihedral_before) {
  const int n = static_cast<int>(body.nodes.size());
  std::vector<int> children_of_cut;
  double max_cos_before = -1.0;
  for (int t : c.traversed) {
    const Tetrahedron& tet = body.tets[t];
    max_cos_before =
        std::max(max_cos_before, max_cos_dihedral(w.current[tet[0]], w.current[tet[1]],
                                                  w.current[tet[2]], w.current[tet[3]]));
    const TetCutPattern pattern = pattern_of(c, tet, n);
    const auto children = decompose(pattern);
    if (children.empty()) continue;
    int local[10];
    for (int i = 0; i < 4; ++i)
      local[i] = tet[i];
    for (int e = 0; e < 6; ++e) {
      if (!pattern.edge_cut[e]) continue;
      const std::uint64_t key = edge_key(tet[kTetEdges[e][0]], tet[kTetEdges[e][1]]);
      const auto it = std::lower_bound(c.cut_edges.begin(), c.cut_edges.end(), key);
      local[4 + e] = n + static_cast<int>(it - c.cut_edges.begin());
    }
    for (std::size_t k = 0; k < children.size(); ++k) {
      Tetrahedron child{local[children[k][0]], local[children[k][1]], local[children[k][2]],
                        local[children[k][3]]};
      const auto& x = w.current;
      if (core::signed_volume(x[child[0]], x[child[1]], x[child[2]], x[child[3]]) < 0) {
        std::swap(child[2], child[3]);
      }
      if (k == 0) {
        w.tets[t] = child;
        children_of_cut.push_back(t);
      } else {
        children_of_cut.push_back(static_cast<int>(w.tets.size()));
        w.tets.push_back(child);
        w.parent.push_back(t);
      }
    }
  }
  min_dihedral_before = c.traversed.empty() ? 180.0 : dihedral_degrees(max_cos_before);
  return children_of_cut;
}

// Twice the longest edge around node v: the reach of its nearest-surface query.
double star_reach(const CutWork& w, int v) {
  double longest = 0.0;
  for (int k = w.star_offset[v]; k < w.star_offset[v + 1]; ++k) {
    for (int u : w.tets[w.star_tets[k]])
      longest = std::max(longest, (w.current[u] - w.current[v]).norm());
  }
  return 2.0 * longest;
}

// The relaxation's node classes (seed 000 §5.1): nodes of poor new tets, except nodes on the
// body's surface, fixed nodes and nodes on cut surface edges; nodes on the cut slide on it.
std::vector<RelaxedNode> relaxation_nodes(const core::TetMesh& body, const CutWork& w,
                                          const std::vector<int>& children,
                                          const CutSurfaceIndex& index,
                                          const RelaxationOptions& options) {
  const int n = static_cast<int>(body.nodes.size());
  std::vector<std::uint8_t> on_surface(w.rest.size(), 0);
  for (const auto& f : body.surface_faces) {
    for (int v : f)
      on_surface[v] = 1;
  }
  for (int v = n; v < static_cast<int>(w.rest.size()); ++v) {
    const auto& s = w.origin[v];  // an edge node lies on the surface when both ends do
    on_surface[v] = s.size() == 2 && on_surface[s[0].old_node] && on_surface[s[1].old_node];
  }
  const double threshold = std::cos(options.relax_below_degrees * M_PI / 180.0);
  std::vector<std::uint8_t> chosen(w.rest.size(), 0);
  std::vector<RelaxedNode> nodes;
  for (int t : children) {
    const Tetrahedron& c = w.tets[t];
    if (tet_is_fit(w.current[c[0]], w.current[c[1]], w.current[c[2]], w.current[c[3]], threshold)) {
      continue;
    }
    for (int v : c) {
      if (chosen[v] || on_surface[v]) continue;
      if (v < n && !body.fixed.empty() && body.fixed[v]) continue;
      chosen[v] = 1;
      RelaxedNode r{v, Vec3::Zero()};
      if (w.on_cut[v]) {
        const auto near = index.nearest(w.current[v], star_reach(w, v));
        if (!near) continue;
        r.slide_normal = near->normal;
      }
      nodes.push_back(r);
    }
  }
  std::sort(nodes.begin(), nodes.end(),
            [](const RelaxedNode& a, const RelaxedNode& b) { return a.node < b.node; });
  return nodes;
}

std::int8_t side_of_tet(const Tetrahedron& t, const CutClassification& c, int old_nodes,
                        const CutWork& w, const CutSurfaceIndex& index) {
  for (int v : t) {
    if (v < old_nodes && (c.side[v] == 1 || c.side[v] == -1)) return c.side[v];
  }
  const Vec3 centroid =
      0.25 * (w.current[t[0]] + w.current[t[1]] + w.current[t[2]] + w.current[t[3]]);
  double longest = 0.0;
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j)
      longest = std::max(longest, (w.current[t[i]] - w.current[t[j]]).norm());
  }
  const auto near = index.nearest(centroid, 3.0 * longest);
  if (!near || std::abs(near->signed_distance) < 1e-15) return 0;
  return near->signed_distance > 0 ? 1 : -1;
}

TopologyChange cut_body(const core::TetMesh& body, const std::vector<Vec3>& current,
                        const CutSurface& cut, const core::SurfaceMesh* visual,
                        const core::SurfaceEmbedding* embedding, const HybridCutOptions& options) {
  check_input(body, current, cut, options);
  // Grid cells about twice the body's mean edge length (a regular tet of the mean volume).
  const double current_volume = volume_of(body.tets, current);
  const double mean_volume = std::abs(current_volume) / body.tets.size();
  const double edge = std::cbrt(6.0 * std::sqrt(2.0) * mean_volume);
  const CutSurfaceIndex index(cut, std::max(edge, 1e-3 * mean_cut_edge(cut)));
  const CutClassification c =
      classify_cut(body, current, index, {options.snap_fraction, options.min_dihedral_degrees});
  if (c.traversed.empty()) {
    TopologyChange change = unchanged(body, current);
    if (visual) change.visual = *visual, change.visual_embedding = *embedding;
    return change;
  }
  const int n = static_cast<int>(body.nodes.size());
  CutWork w;
  w.rest = body.nodes;
  w.current = current;
  w.tets = body.tets;
  w.parent.resize(body.tets.size());
  for (std::size_t t = 0; t < body.tets.size(); ++t)
    w.parent[t] = static_cast<int>(t);
  w.origin.resize(n);
  w.on_cut.assign(n, 0);
  for (int v = 0; v < n; ++v)
    w.on_cut[v] = c.side[v] == 0;
  for (std::uint64_t key : c.cut_edges) {
    const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
    const double t = c.hits.at(key).t;
    w.rest.push_back((1.0 - t) * body.nodes[a] + t * body.nodes[b]);
    w.current.push_back((1.0 - t) * current[a] + t * current[b]);
    w.origin.push_back({{a, 1.0 - t}, {b, t}});
    w.on_cut.push_back(1);
  }
  TopologyChange change;
  CutStatistics& s = change.statistics;
  s.tets_before = body.tets.size();
  s.tets_traversed = c.traversed.size();
  s.nodes_snapped = c.snapped;
  s.nodes_created = c.cut_edges.size();
  s.rest_volume_before = volume_of(body.tets, body.nodes);
  s.current_volume_before = current_volume;
  const std::vector<int> children = decompose_traversed(body, c, w, s.min_dihedral_before_degrees);
  std::vector<int> decomposed_parents;
  for (int t : children)
    decomposed_parents.push_back(w.parent[t]);
  std::sort(decomposed_parents.begin(), decomposed_parents.end());
  s.tets_decomposed =
      static_cast<std::size_t>(std::unique(decomposed_parents.begin(), decomposed_parents.end()) -
                               decomposed_parents.begin());
  build_stars(w);
  RelaxationMesh rm{&w.tets, &w.current, &w.rest, &w.star_offset, &w.star_tets, &w.origin};
  s.nodes_relaxed = static_cast<std::size_t>(relax_cut_neighbourhood(
      rm, relaxation_nodes(body, w, children, index, options.relaxation), options.relaxation));
  // Sides of the tets around nodes on the cut, then node separation.
  std::vector<std::int8_t> tet_side(w.tets.size(), 0);
  for (int v = 0; v < static_cast<int>(w.rest.size()); ++v) {
    if (!w.on_cut[v]) continue;
    for (int k = w.star_offset[v]; k < w.star_offset[v + 1]; ++k) {
      const int t = w.star_tets[k];
      tet_side[t] = side_of_tet(w.tets[t], c, n, w, index);
    }
  }
  const SeparationResult separation = separate_cut_nodes(w, tet_side);
  s.nodes_duplicated = separation.duplicated;
  if (children.empty() && separation.duplicated == 0) {
    // The surface only touched nodes without separating anything: nothing changes.
    TopologyChange same = unchanged(body, current);
    same.statistics.tets_traversed = c.traversed.size();
    same.statistics.nodes_snapped = c.snapped;
    if (visual) same.visual = *visual, same.visual_embedding = *embedding;
    return same;
  }
  // Assemble the change.
  change.changed = true;
  change.mesh.nodes = std::move(w.rest);
  change.mesh.tets = w.tets;
  change.mesh.surface_faces = rebuild_surface(body.surface_faces, body.tets, w, separation,
                                              change.cut_surface_faces, change.cut_face_tets);
  change.current = std::move(w.current);
  change.tet_parent = w.parent;
  change.on_cut = w.on_cut;
  const int total = static_cast<int>(change.mesh.nodes.size());
  change.node_source_offset.reserve(total + 1);
  change.node_source_offset.push_back(0);
  for (int v = 0; v < total; ++v) {
    if (w.origin[v].empty()) {
      change.node_source.push_back({v, 1.0});
    } else {
      change.node_source.insert(change.node_source.end(), w.origin[v].begin(), w.origin[v].end());
    }
    change.node_source_offset.push_back(static_cast<int>(change.node_source.size()));
  }
  if (!body.tet_labels.empty()) {
    for (int p : change.tet_parent)
      change.mesh.tet_labels.push_back(body.tet_labels[p]);
  }
  if (!body.fixed.empty()) {
    change.mesh.fixed.assign(total, 0);
    for (int v = 0; v < total; ++v) {
      auto [begin, end] = change.sources(v);
      for (auto* src = begin; src != end; ++src) {
        if (src->weight > 1.0 - 1e-12 && body.fixed[src->old_node]) change.mesh.fixed[v] = 1;
      }
    }
  }
  if (!body.node_mass.empty() && s.rest_volume_before > 0.0) {
    double mass = 0.0;
    for (double m : body.node_mass)
      mass += m;
    change.mesh.node_mass = core::lumped_node_masses(change.mesh, mass / s.rest_volume_before);
  }
  s.tets_after = change.mesh.tets.size();
  s.cut_faces = change.cut_surface_faces.size();
  s.rest_volume_after = volume_of(change.mesh.tets, change.mesh.nodes);
  s.current_volume_after = volume_of(change.mesh.tets, change.current);
  double max_cos_after = -1.0;
  for (int t : separation.affected) {
    const Tetrahedron& q = change.mesh.tets[t];
    for (const auto* x : {&change.current, &change.mesh.nodes}) {
      max_cos_after =
          std::max(max_cos_after, max_cos_dihedral((*x)[q[0]], (*x)[q[1]], (*x)[q[2]], (*x)[q[3]]));
    }
  }
  s.min_dihedral_after_degrees =
      separation.affected.empty() ? 180.0 : dihedral_degrees(max_cos_after);
  if (visual) cut_visual_surface(*visual, *embedding, body, current, index, change);
  return change;
}

}  // namespace

TopologyChange hybrid_cut(const core::TetMesh& body, const std::vector<Vec3>& current,
                          const CutSurface& cut, const HybridCutOptions& options) {
  return cut_body(body, current, cut, nullptr, nullptr, options);
}

TopologyChange hybrid_cut(const core::TetMesh& body, const std::vector<Vec3>& current,
                          const CutSurface& cut, const core::SurfaceMesh& visual,
                          const core::SurfaceEmbedding& embedding,
                          const HybridCutOptions& options) {
  if (embedding.tet.size() != visual.vertices.size() ||
      embedding.weights.size() != visual.vertices.size()) {
    throw InputError("the visual surface has " + std::to_string(visual.vertices.size()) +
                     " vertices but its embedding has " + std::to_string(embedding.tet.size()));
  }
  for (std::size_t i = 0; i < embedding.tet.size(); ++i) {
    if (embedding.tet[i] < 0 || embedding.tet[i] >= static_cast<int>(body.tets.size())) {
      throw InputError("visual vertex " + std::to_string(i) + " is embedded in tet " +
                       std::to_string(embedding.tet[i]) + ", which the body does not have");
    }
  }
  return cut_body(body, current, cut, &visual, &embedding, options);
}

void require_sweep_leaves_tissue(const core::TetMesh& body, const std::vector<Vec3>& current,
                                 const LoopElectrode& loop, const std::vector<LoopPose>& sweep) {
  if (sweep.empty()) throw InputError("the loop sweep has no poses");
  if (current.size() != body.nodes.size()) {
    throw InputError("the body has " + std::to_string(body.nodes.size()) + " nodes but " +
                     std::to_string(current.size()) + " current positions");
  }
  const auto inside = [&](const Vec3& p) {
    for (std::size_t t = 0; t < body.tets.size(); ++t) {
      const Tetrahedron& q = body.tets[t];
      core::BoundingBox box;
      for (int v : q)
        box.add(current[v]);
      if ((p.array() < box.min.array()).any() || (p.array() > box.max.array()).any()) continue;
      const auto w =
          core::barycentric(p, current[q[0]], current[q[1]], current[q[2]], current[q[3]]);
      if (std::min({w[0], w[1], w[2], w[3]}) >= 0.0) return static_cast<int>(t);
    }
    return -1;
  };
  for (const auto& [pose, which] :
       {std::pair{sweep.front(), "starts"}, std::pair{sweep.back(), "ends"}}) {
    const auto points = loop_points(loop, pose);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const int t = inside(points[i]);
      if (t < 0) continue;
      throw InputError(std::string("the loop sweep ") + which + " inside the tissue (wire point " +
                       std::to_string(i) + " lies in tet " + std::to_string(t) +
                       "); the loop must traverse the tissue completely before the cut is made");
    }
  }
}

}  // namespace viscera::sim::cutting
