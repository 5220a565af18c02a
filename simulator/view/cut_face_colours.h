#pragma once
/// Colours of a cut organ's inside (issue 17 §2: "new cut faces are ... textured from the
/// organ's solid texture so the inside of a myoma looks like myoma"). The package's albedo maps
/// cover only the organ's skin, baked from a solid texture (Perlin 1985; textures/solid_texture.h)
/// that is defined everywhere in space: evaluated at a cut face's material (rest) points it gives
/// the tissue the cut laid open, continuous with the skin it was baked onto.
///
/// Decisions: the inside carries the preset's colour field and grain but not its vessel layers
/// (those are grown on the surface); the texture is evaluated at the bakers' default scale,
/// textures::ScenarioBakeOptions::texture_scale, because a package does not record a different
/// one; and with the preset's palette, because it does not keep a user's sample image either.

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "core/math_types.h"

namespace viscera::textures {
class SolidTissueTexture;
}

namespace viscera::view {

class CutFaceColours {
 public:
  /// The solid texture of built-in preset `preset` seeded with `seed` (the object's
  /// TextureSpec). Throws core::UsageError naming an unknown preset.
  CutFaceColours(const std::string& preset, std::uint64_t seed);
  ~CutFaceColours();

  /// RGB in 0…1, encoded as the albedo maps are (sRGB), at each material point in m.
  std::vector<std::array<double, 3>> at(const std::vector<core::Vec3>& material_points) const;

 private:
  std::unique_ptr<textures::SolidTissueTexture> texture_;
};

}  // namespace viscera::view
