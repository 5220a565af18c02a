#pragma once
/// Baking surface textures into a UV atlas (seed 000 §7: "New textures are synthesized and
/// automatically mapped onto the object geometries"): every texel whose centre falls in a
/// triangle of the UV layout is shaded at the matching surface point; normals are written in
/// the triangle's tangent frame; empty texels next to charts are filled from their neighbours
/// (gutters), so mip-mapping and bilinear filtering never pull in background.

#include "core/mesh/surface_mesh.h"
#include "core/progress.h"
#include "textures/surface_shader.h"
#include "textures/texture_synthesis.h"

namespace viscera::textures {

/// Size of the baked maps.
struct BakeOptions {
  int width = 1024;
  int height = 1024;
  int gutter = 4;   ///< texels of dilation around every chart
  int threads = 0;  ///< 0 = one per hardware thread; never changes the result
};

/// Bakes `shader` over mesh.uvs (texel (x, y) ↔ u = (x + ½)/W, v = 1 − (y + ½)/H). The normal
/// map is tangent-space with +u right and +v up (as texture_synthesis.h). Vertex normals are
/// used when present (else computed). Throws core::UsageError when the mesh has no UVs or the
/// size is outside [8, 16384]; CancelledError through `progress`.
TextureMaps bake_surface_texture(const core::SurfaceMesh& mesh, const SurfaceShader& shader,
                                 const BakeOptions& options,
                                 core::Progress& progress = core::Progress::none());

}  // namespace viscera::textures
