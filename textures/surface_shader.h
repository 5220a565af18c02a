#pragma once
/// What a baker asks of a texture: the look of an organ surface at a point.

#include "core/math_types.h"
#include "textures/sample_noise_field.h"

namespace viscera::textures {

/// Shading of one surface point: sRGB albedo in [0, 255], the perturbed unit normal in world
/// space, and wetness (specular) in [0, 1].
struct SurfaceSample {
  Rgb albedo{};
  core::Vec3 normal = core::Vec3::UnitZ();
  float wetness = 0.0f;
};

/// A texture defined on surfaces in space: solid textures and triplanar projections.
class SurfaceShader {
 public:
  virtual ~SurfaceShader() = default;
  /// Shades the surface point p (m) with unit normal n; texel_size (m) is the footprint of the
  /// sample, for anti-aliasing and finite differences. Safe to call from several threads.
  virtual SurfaceSample shade(const core::Vec3& p, const core::Vec3& n,
                              double texel_size) const = 0;
};

}  // namespace viscera::textures
