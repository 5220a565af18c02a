#pragma once
/// What a cut hands to the simulation core: the new topology of one body and everything the
/// core needs to carry its per-node and per-tet state over (seed 000 §5.1: "after a cut has been
/// performed, we update the mesh parameters to keep the underlying deformation simulation
/// stable"). The core's `topology_changed()` consumes it; nothing here touches simulator state.
///
/// Carrying state over (the whole contract):
/// - per-node arrays (velocities, previous positions, fixed flags, plastic rest data, …): for
///   every node i of the new mesh, new[i] = Σ_k weight_k · old[source_k] over
///   node_sources(i). Unchanged old nodes have the single source (i, 1); a node duplicated by
///   the cut has (old node, 1) in each copy; a node created on a cut edge has the edge's two end
///   nodes with weights (1 − t, t); a node moved by the relaxation has the barycentric weights
///   of its new place in the old mesh. Weights are ≥ 0 and sum to 1. Flags (fixed) should be
///   carried as "any source with weight 1 is fixed", not interpolated.
/// - positions: `mesh.nodes` are the new REST positions (m) and `current` the new deformed
///   positions (m); both are given explicitly, computed with the same weights.
/// - per-tet arrays (labels, materials, plastic rest volumes): new tet j comes from old tet
///   tet_parent[j]; rest quantities must be recomputed from the new rest positions (a child tet
///   is a piece of its parent). `mesh.tet_labels` is already carried.
/// - masses: `mesh.node_mass` is recomputed as lumped masses of the rest volumes times the
///   density implied by the old masses (old total mass / old rest volume), so the total mass is
///   unchanged; `mesh.fixed` is carried by the rule above.
/// - old node indices keep their meaning (node i < old node count is the same material point,
///   possibly moved a little by the relaxation); new nodes are appended. Old tet indices keep
///   their meaning for unchanged tets; a decomposed tet's first child takes its index and the
///   other children are appended.

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/mesh/surface_embedding.h"
#include "core/mesh/surface_mesh.h"
#include "core/mesh/tet_mesh.h"

namespace viscera::sim::cutting {

/// One contribution of an old node to a node of the new mesh.
struct NodeSource {
  int old_node = 0;
  double weight = 0.0;

  bool operator==(const NodeSource&) const = default;
};

/// Figures of one cut, for the session report's `cutting` block (issue 17 §5).
struct CutStatistics {
  std::size_t tets_before = 0;
  std::size_t tets_after = 0;
  std::size_t tets_traversed =
      0;  ///< tets the cut surface passes through (decomposed or separated)
  std::size_t tets_decomposed = 0;
  std::size_t nodes_snapped = 0;     ///< existing nodes the cut was moved onto (node snapping)
  std::size_t nodes_created = 0;     ///< nodes on cut edges
  std::size_t nodes_duplicated = 0;  ///< copies made by node separation
  std::size_t nodes_relaxed = 0;     ///< nodes the Lennard-Jones relaxation moved
  std::size_t cut_faces = 0;         ///< tet faces that became surface, both sides counted
  double rest_volume_before = 0.0;   ///< m³
  double rest_volume_after = 0.0;    ///< m³
  double current_volume_before = 0.0;
  double current_volume_after = 0.0;
  double min_dihedral_before_degrees = 0.0;  ///< over the tets the cut replaced, current config
  double min_dihedral_after_degrees = 0.0;   ///< over the tets it created, both configs
};

/// The result of a cut on one body. When `changed` is false the cut neither decomposed nor
/// separated anything (it missed the body or only touched nodes); every other field then still
/// describes the unchanged body (identity sources and parents), so it can be applied blindly.
struct TopologyChange {
  bool changed = false;
  core::TetMesh mesh;               ///< new topology; nodes = rest positions in m
  std::vector<core::Vec3> current;  ///< deformed positions in m, one per mesh node
  /// CSR: the sources of node i are node_source[node_source_offset[i] …
  /// node_source_offset[i + 1]). node_source_offset.size() == mesh.nodes.size() + 1.
  std::vector<int> node_source_offset;
  std::vector<NodeSource> node_source;
  std::vector<int> tet_parent;  ///< per new tet: the old tet it is (a piece of)
  /// Surface faces that lie on the cut (new surface, both sides), indices into
  /// mesh.surface_faces. The core gives them the area energy like every surface face.
  std::vector<int> cut_surface_faces;
  std::vector<int> cut_face_tets;  ///< per cut surface face: the tet it bounds
  /// Per mesh node: 1 when it lies on the cut (a snapped node, a node on a cut edge, or a copy).
  std::vector<std::uint8_t> on_cut;
  /// The visual surface after the cut and its embedding in `mesh` (empty when none was given).
  /// Its vertex attribute "cut_face" is 1 on vertices of cut triangles and "material_x",
  /// "material_y", "material_z" hold each vertex's rest (material) position in m, the point at
  /// which the organ's solid texture is evaluated (textures/solid_texture.h).
  core::SurfaceMesh visual;
  core::SurfaceEmbedding visual_embedding;
  std::vector<int> visual_cut_triangles;  ///< indices into visual.triangles of cut faces
  CutStatistics statistics;

  /// The sources of node i as a span-like pair of pointers.
  std::pair<const NodeSource*, const NodeSource*> sources(int node) const {
    return {node_source.data() + node_source_offset[node],
            node_source.data() + node_source_offset[node + 1]};
  }
};

/// Applies the node-source rule to one per-node array (values of the old mesh).
template <typename T>
std::vector<T> carry_node_values(const TopologyChange& change, const std::vector<T>& old_values) {
  std::vector<T> values;
  values.reserve(change.mesh.nodes.size());
  for (int i = 0; i + 1 < static_cast<int>(change.node_source_offset.size()); ++i) {
    auto [begin, end] = change.sources(i);
    T sum = old_values[begin->old_node] * begin->weight;
    for (const NodeSource* s = begin + 1; s != end; ++s)
      sum += old_values[s->old_node] * s->weight;
    values.push_back(sum);
  }
  return values;
}

}  // namespace viscera::sim::cutting
