#pragma once
/// How tissue texels are put together from their fields; shared by the flat texture synthesiser
/// and the solid texture that is baked onto organs, so both look alike.

#include <algorithm>
#include <cstddef>

#include "textures/texture_preset.h"

namespace viscera::textures {

/// Mean of Perlin turbulence divided by its amplitude sum (measured over 2·10⁵ points, 4 octaves,
/// persistence 0.5: 0.21 in the plane and in space); grain darkens above it and brightens below,
/// so it keeps the mean colour.
inline constexpr float kTurbulenceMean = 0.21f;

/// Inputs of `count` texels. turbulence[i]·turbulence_scale is the normalised turbulence in
/// [0, 1); wetness_noise[i]·wetness_scale the normalised fractal sum in about [-1, 1] (nullptr: 0);
/// coverage[l][i], depth[l][i] vessel layer l (coverage[l] may be nullptr: no vessels).
struct TissueFields {
  int count = 0;
  const float* base_rgb = nullptr;  ///< colour field, interleaved RGB
  const double* turbulence = nullptr;
  double turbulence_scale = 1.0;
  const double* wetness_noise = nullptr;
  double wetness_scale = 1.0;
  const float* const* coverage = nullptr;
  const float* const* depth = nullptr;
};

/// Shades `fields.count` texels: albedo_rgb interleaved sRGB in about [0, 255], height in height
/// units, wetness in [0, 1]. Grain scales the base colour; each vessel layer is blended over it
/// with an opacity and colour that fade with depth (seed 001 §3.3).
inline void shade_tissue(const TexturePreset& preset, const TissueFields& f, float* albedo_rgb,
                         float* height, float* wetness) {
  const auto contrast = static_cast<float>(preset.grain_contrast);
  const auto grain_height = static_cast<float>(preset.grain_height);
  const auto turbulence_scale = static_cast<float>(f.turbulence_scale);
  const auto wet_base = static_cast<float>(preset.specular_base);
  const auto wet_variation = static_cast<float>(preset.specular_variation * f.wetness_scale);
  for (int i = 0; i < f.count; ++i) {
    const float t = static_cast<float>(f.turbulence[i]) * turbulence_scale;
    const float gain = 1.0f + contrast * (kTurbulenceMean - t);
    for (int k = 0; k < 3; ++k)
      albedo_rgb[3 * i + k] = f.base_rgb[3 * i + k] * gain;
    height[i] = grain_height * t;
  }
  if (f.wetness_noise) {
    for (int i = 0; i < f.count; ++i)
      wetness[i] = wet_base + wet_variation * static_cast<float>(f.wetness_noise[i]);
  } else {
    for (int i = 0; i < f.count; ++i)
      wetness[i] = wet_base;
  }
  for (std::size_t l = 0; l < preset.vessels.size(); ++l) {
    if (!f.coverage || !f.coverage[l]) continue;
    const auto& layer = preset.vessels[l];
    const auto opacity = static_cast<float>(layer.opacity);
    const auto fade = static_cast<float>(layer.depth_fade);
    const auto bump = static_cast<float>(layer.height);
    const auto wet = static_cast<float>(layer.wetness);
    for (int i = 0; i < f.count; ++i) {
      const float c = f.coverage[l][i];
      if (c <= 0.0f) continue;
      const float d = std::clamp(f.depth[l][i], 0.0f, 1.0f);
      const float t = static_cast<float>(f.turbulence[i]) * turbulence_scale;
      const float gain = 1.0f + contrast * (kTurbulenceMean - t);
      // Deeper vessels are seen through more tissue: fainter and shifted towards blue-violet.
      const float alpha = c * opacity * (1.0f - fade * d);
      for (int k = 0; k < 3; ++k) {
        const float vessel = (layer.color[k] + d * (layer.deep_color[k] - layer.color[k])) * gain;
        albedo_rgb[3 * i + k] += alpha * (vessel - albedo_rgb[3 * i + k]);
      }
      height[i] += bump * c * (1.0f - d);
      wetness[i] += wet * c;
    }
  }
  for (int i = 0; i < f.count; ++i)
    wetness[i] = std::clamp(wetness[i], 0.0f, 1.0f);
}

}  // namespace viscera::textures
