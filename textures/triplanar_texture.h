#pragma once
/// Triplanar projection of flat texture maps (e.g. a `viscera texture` result or a photograph)
/// for surfaces without usable UVs: each map is projected along the three axes and the three
/// samples are blended by |n|^sharpness, so no parameterisation and no seams are needed.
/// Normals use the "UDN" blend (Golus 2017, "Normal Mapping for a Triplanar Shader").

#include "core/mesh/surface_mesh.h"
#include "textures/surface_shader.h"
#include "textures/texture_synthesis.h"

namespace viscera::textures {

/// A SurfaceShader over flat maps that tile every texture_scale metres.
class TriplanarTexture final : public SurfaceShader {
 public:
  /// `maps` needs an albedo; a missing normal map means flat, a missing specular map means 0.5.
  /// Throws core::UsageError for an empty albedo or a non-positive scale.
  TriplanarTexture(TextureMaps maps, double texture_scale, double sharpness = 4.0);

  SurfaceSample shade(const core::Vec3& p, const core::Vec3& n, double texel_size) const override;

 private:
  /// Bilinear, wrapped sample of channel values at texture coordinates (u, v) in widths.
  void sample(const Image8& image, double u, double v, float* out) const;

  TextureMaps maps_;
  double scale_;
  double sharpness_;
};

/// Shades every vertex and stores the result as vertex attributes "albedo_r", "albedo_g",
/// "albedo_b" and "wetness" in [0, 1]: the last resort for surfaces that keep their topology
/// and have no UVs. Normals are computed when absent.
void bake_vertex_colors(core::SurfaceMesh& mesh, const SurfaceShader& shader);

}  // namespace viscera::textures
