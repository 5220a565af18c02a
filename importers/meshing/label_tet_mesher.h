#pragma once
/// Label map → tetrahedra directly with CGAL Mesh_3 (issue 3 §4a): Delaunay refinement of the
/// labelled image domain (Labeled_mesh_domain_3 over the labels' trilinear indicator functions;
/// Rineau & Yvinec 2007, Jamin et al. 2015) under facet and cell criteria, optionally sliver
/// exudation (Cheng et al. 2000). Each tet keeps the label of the region it fills. Sequential
/// by default (same input → same bytes); `threads` > 1 runs Mesh_3's parallel mode on TBB
/// (CGAL::Parallel_tag), which is faster but not deterministic.

#include <cstddef>
#include <map>
#include <string>

#include "core/image/image_volume.h"
#include "core/mesh/tet_mesh.h"
#include "core/progress.h"

namespace viscera::importers {

/// Mesh_3 criteria and choices. Lengths in m; 0 picks the documented default.
struct LabelTetMeshingOptions {
  int label = 0;  ///< mesh only this label; 0 = every label other than 0
  /// Upper bound of the tets' circumradius, m. 0 = from `target_tets`.
  double cell_size = 0.0;
  /// Approximate tet count used when cell_size is 0: the cell size is chosen from the labelled
  /// volume (about 0.2·s³ per tet at the default criteria), never below 1.5 voxel spacings.
  std::size_t target_tets = 150000;
  std::map<int, double> label_cell_size;  ///< per-label cell size, m (overrides cell_size)
  double cell_radius_edge_ratio = 3.0;    ///< upper bound of circumradius / shortest edge
  double facet_angle_degrees = 30.0;      ///< lower bound of the boundary facets' angles
  double facet_size = 0.0;                ///< upper bound of facet circumradius, m; 0 = cell size
  /// Upper bound of the distance between a facet's circumcentre and the labels' boundary, m;
  /// 0 = a sixth of the facet size, kept between half and one smallest voxel spacing (the
  /// boundary is not refined below what its facets resolve, nor below the voxel staircase).
  double facet_distance = 0.0;
  bool exude = true;  ///< sliver exudation after refinement (no time limit: deterministic)
  /// Exudation works on tets whose smallest dihedral angle is below this, degrees; 0 lets it
  /// improve the worst angle as far as it goes (on CGAL's liver: 21 s instead of 1 s for 130k
  /// tets, issue 20).
  double exude_sliver_bound_degrees = 12.0;
  int threads = 1;    ///< > 1: CGAL::Parallel_tag on TBB with this many threads
  unsigned seed = 1;  ///< Mesh_3's random generator (initial boundary points)
};

/// The criteria actually used, after defaults were resolved (m).
struct ResolvedTetCriteria {
  double cell_size = 0.0;
  double facet_size = 0.0;
  double facet_distance = 0.0;
};

/// Resolves the defaults of `options` for `labels` (the crop's labelled volume sets the cell
/// size for target_tets). Throws as mesh_label_map.
ResolvedTetCriteria resolve_tet_criteria(const core::LabelMap& labels,
                                         const LabelTetMeshingOptions& options,
                                         const std::string& what);

/// Tetrahedra filling the labelled voxels, in metres in the map's world frame, positively
/// oriented, with tet_labels and outward surface_faces (no masses, nothing fixed).
/// Throws core::InputError naming `what` for an empty map or a label without voxels,
/// core::UsageError for criteria out of range, core::ValidationError when Mesh_3 finds no
/// tetrahedra (a region thinner than the criteria resolve), CancelledError. `used`, when given,
/// receives the resolved criteria.
core::TetMesh mesh_label_map(const core::LabelMap& labels, const LabelTetMeshingOptions& options,
                             const std::string& what,
                             core::Progress& progress = core::Progress::none(),
                             ResolvedTetCriteria* used = nullptr);

}  // namespace viscera::importers
