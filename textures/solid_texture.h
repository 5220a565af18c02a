#pragma once
/// Tissue presets as solid textures (Perlin 1985: textures defined in space, so they need no
/// parameterisation and show no seams): the sample-image colour field and the turbulence grain
/// are evaluated at the 3D point, and vessels are L-system trees grown on the organ's surface
/// (seed 001 §3.3, seed 000 §7). Baked into UV atlases by texture_baker.h.

#include <cstdint>
#include <memory>
#include <vector>

#include "core/lsystem/turtle.h"
#include "textures/perlin_noise.h"
#include "textures/surface_projector.h"
#include "textures/surface_shader.h"
#include "textures/texture_preset.h"
#include "textures/tissue_shading.h"

namespace viscera::textures {

/// Vessel layers of a preset grown on a surface: each tree starts at a random surface point in
/// a random tangent direction and its turtle is projected back onto the surface after every step
/// with its up vector along the surface normal, so the tree hugs the organ. Lengths and widths
/// are the preset's texture-width fractions times texture_scale (m per texture width); the tree
/// count scales with the surface area over texture_scale². Strokes in m.
std::vector<std::vector<core::TurtleSegment>> grow_surface_vessels(const TexturePreset& preset,
                                                                   const SurfaceProjector& surface,
                                                                   double texture_scale,
                                                                   std::uint64_t seed);

/// A preset evaluated in space. Safe to share between threads.
class SolidTissueTexture final : public SurfaceShader {
 public:
  /// texture_scale: metres per texture width (the preset's frequencies are per width).
  /// sample: the user's sample image, or nullptr for the preset's palette. vessel_layers: one
  /// stroke list per preset vessel layer (grow_surface_vessels), or empty for none.
  SolidTissueTexture(const TexturePreset& preset, std::uint64_t seed, double texture_scale,
                     const Image8* sample,
                     std::vector<std::vector<core::TurtleSegment>> vessel_layers = {});
  ~SolidTissueTexture() override;

  /// Albedo, height and wetness at p; texel_size (m) anti-aliases vessel edges.
  void texel(const core::Vec3& p, double texel_size, Rgb& albedo, float& height,
             float& wetness) const;
  /// Height only (grain and vessel bumps), for normals.
  float height(const core::Vec3& p, double texel_size) const;

  /// Normal from the height field's surface gradient: n' = normalise(n − k·scale·∇ₛh), the
  /// solid counterpart of normal_map_from_height.
  SurfaceSample shade(const core::Vec3& p, const core::Vec3& n, double texel_size) const override;

 private:
  struct VesselIndex;
  void vessel_coverage(const core::Vec3& p, double texel_size, float* coverage, float* depth) const;

  TexturePreset preset_;
  double scale_;
  SampleNoiseField colors_;
  PerlinNoise grain_, wetness_;
  std::vector<std::unique_ptr<VesselIndex>> vessels_;
};

}  // namespace viscera::textures
