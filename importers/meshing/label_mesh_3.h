#pragma once
/// The Mesh_3 run behind mesh_label_map(), in the crop's own frame (millimetres, voxel (0,0,0)
/// at the origin: CGAL 5.5 mishandles labelled images with a non-zero origin). Two translation
/// units instantiate it, sequential and parallel, so each compiles once and in parallel.

#include <array>
#include <atomic>
#include <map>
#include <vector>

#include "core/math_types.h"
#include "importers/meshing/label_crop.h"

namespace viscera::importers::detail {

/// Criteria in millimetres and the crop they apply to.
struct Mesh3Input {
  const LabelCrop* crop = nullptr;
  core::Vec3 spacing_mm = core::Vec3::Ones();
  double cell_size_mm = 1.0;
  std::map<int, double> label_cell_size_mm;
  double cell_radius_edge_ratio = 3.0;
  double facet_angle_degrees = 30.0;
  double facet_size_mm = 1.0;
  double facet_distance_mm = 0.5;
  bool exude = true;
  /// Exudation stops once every tet's smallest dihedral angle reaches this, degrees (0: CGAL's
  /// default, improve the worst angle as far as it goes).
  double exude_sliver_bound_degrees = 0.0;
  int threads = 1;
  unsigned seed = 1;
  /// Set (from another thread) to stop refinement early; the output is then incomplete.
  std::atomic<bool>* stop = nullptr;
};

/// Tets of the complex, positively oriented in the crop frame, with their subdomain labels.
struct Mesh3Output {
  std::vector<core::Vec3> nodes_mm;
  std::vector<core::Tetrahedron> tets;
  std::vector<int> labels;
};

Mesh3Output run_mesh_3_sequential(const Mesh3Input& input);
Mesh3Output run_mesh_3_parallel(const Mesh3Input& input);

}  // namespace viscera::importers::detail
