#pragma once
/// Texture atlases for organ surfaces: automatic seams (uv_charts.h), each chart flattened by
/// least squares conformal maps (Lévy et al. 2002; CGAL Surface_mesh_parameterization
/// LSCM_parameterizer_3), charts scaled to one texel density and packed into the unit square
/// with gutters, and distortion measured (Sander et al. 2001, "Texture mapping progressive
/// meshes": L² stretch).

#include <vector>

#include "core/mesh/surface_mesh.h"

namespace viscera::textures {

/// How the atlas is laid out.
struct UvAtlasOptions {
  int resolution = 1024;  ///< texels along the atlas side the gutters are measured in
  int gutter = 4;         ///< texels of empty space around every chart
};

/// The surface cut along its seams: vertices on a seam appear once per chart. Triangles keep
/// their order; positions, normals and vertex attributes are copied from the original vertex.
struct UvAtlas {
  core::SurfaceMesh mesh;            ///< with uvs in [0, 1]²
  std::vector<int> original_vertex;  ///< per atlas vertex
  std::vector<int> chart_of_triangle;
  int chart_count = 0;
  int lscm_fallbacks = 0;  ///< charts flattened by projection because LSCM failed or folded
};

/// Builds the atlas. The input needs at least one triangle; normals are computed when absent so
/// that seam vertices keep smooth shading. Throws core::InputError for an empty mesh.
UvAtlas build_uv_atlas(const core::SurfaceMesh& mesh, const UvAtlasOptions& options = {});

/// How much a parameterisation distorts. Triangle measures are area-weighted over the surface
/// after scaling the whole map to the surface's area, so a perfect map has 1 everywhere.
struct UvDistortion {
  double l2_stretch = 0.0;      ///< Sander's L² stretch: √(Σ A·(Γ²+γ²)/2 / Σ A), ≥ 1
  double mean_conformal = 0.0;  ///< mean Γ/γ (angle distortion), ≥ 1
  double max_conformal = 0.0;
  double area_ratio_p05 = 0.0;  ///< 5th percentile of texel area per surface area (1 = even)
  double area_ratio_p95 = 0.0;  ///< 95th percentile
  int flipped = 0;              ///< triangles with non-positive UV area
  int degenerate = 0;           ///< triangles with zero 3D area (skipped)
};

/// Measures the distortion of mesh.uvs. Throws core::UsageError when there are no UVs.
UvDistortion measure_uv_distortion(const core::SurfaceMesh& mesh);

/// True when the mesh's UVs can carry a baked texture: one per vertex, finite, inside [0, 1]²,
/// no flipped triangle, L² stretch below 2, and no two triangles sharing a texel of a 512²
/// raster (no overlap). Spherical UVs of an icosphere, for instance, fail at their seam.
bool has_usable_uvs(const core::SurfaceMesh& mesh);

}  // namespace viscera::textures
