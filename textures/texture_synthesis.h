#pragma once
/// Flat tissue textures: albedo (sample-image colour field × Perlin turbulence grain, plus
/// L-system vessel layers), a tangent-space normal map from the height field, and a specular
/// (wetness) map (seed 001 §3.3; seed 000 §7: bump mapping for rough surfaces, environment
/// mapping for wet, specular ones).

#include <cstdint>

#include "core/progress.h"
#include "textures/image8.h"
#include "textures/texture_preset.h"

namespace viscera::textures {

/// What to synthesise.
struct TextureOptions {
  std::uint64_t seed = 1;
  int width = 1024;                 ///< pixels
  int height = 1024;                ///< pixels
  const Image8* sample = nullptr;   ///< user sample image (RGB); nullptr = the preset's palette
  bool vessels = true;              ///< paint the preset's vessel layers
  bool normal_and_specular = true;  ///< also make the normal and specular maps
  int threads = 0;                  ///< 0 = one per hardware thread; never changes the result
};

/// The maps of one texture. normal: RGB = (n + 1)/2 in tangent space, +u to the right, +v up
/// the image (OpenGL convention); specular: wetness in [0, 255].
struct TextureMaps {
  Image8 albedo;    ///< 3 channels
  Image8 normal;    ///< 3 channels, empty unless requested
  Image8 specular;  ///< 1 channel, empty unless requested
};

/// Synthesises the maps. Lengths of the preset are in texture widths, so every size shows the
/// same tissue. The same (preset, options) give the same pixels on any thread count.
/// Throws core::UsageError for sizes outside [8, 16384] and core::InputError for an empty
/// sample; CancelledError through `progress`.
TextureMaps synthesize_texture(const TexturePreset& preset, const TextureOptions& options,
                               core::Progress& progress = core::Progress::none());

/// Normal map of a height field h (width × height floats, height units) with strength k:
/// n = normalise(−k ∂h/∂u, −k ∂h/∂v, 1), u and v in texture widths, central differences
/// clamped at the border.
Image8 normal_map_from_height(const std::vector<float>& height_field, int width, int height,
                              double strength, int threads = 0);

}  // namespace viscera::textures
