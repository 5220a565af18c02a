#pragma once
/// Automatic seams: cutting an organ surface into charts that are topological disks, each
/// gently curved, so that each flattens with little distortion (the chart growing of Lévy et al.
/// 2002, "Least Squares Conformal Maps for Automatic Texture Atlas Generation", in its simplest
/// form: faces grouped by the axis their normal is closest to, as in a cube map).

#include <vector>

#include "core/mesh/surface_mesh.h"

namespace viscera::textures {

/// Chart index of every triangle, 0 … chart_count − 1. Every chart is edge-connected and a
/// topological disk (one boundary loop, Euler characteristic 1): charts that are not are split
/// until they are. Non-manifold edges always become seams. Works on open and closed surfaces.
struct ChartSegmentation {
  std::vector<int> chart_of_triangle;
  int chart_count = 0;
};

/// Segments `mesh` into charts; `smoothing_passes` majority-vote passes straighten the seams.
ChartSegmentation segment_charts(const core::SurfaceMesh& mesh, int smoothing_passes = 3);

/// True when the given triangles, as a surface of their own, are a connected topological disk.
bool is_topological_disk(const core::SurfaceMesh& mesh, const std::vector<int>& triangles);

}  // namespace viscera::textures
