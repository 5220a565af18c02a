#include "simulator/view/cut_face_colours.h"

#include <algorithm>

#include "textures/scenario_baking.h"
#include "textures/solid_texture.h"
#include "textures/texture_preset.h"

namespace viscera::view {
namespace {

/// The size of one albedo texel on the organ, m: the vessel-free field needs no finer
/// anti-aliasing than the cut faces' own size.
constexpr double kTexelSize = 2e-4;

}  // namespace

CutFaceColours::CutFaceColours(const std::string& preset, std::uint64_t seed)
    : texture_(std::make_unique<textures::SolidTissueTexture>(
          textures::find_texture_preset(preset), seed,
          textures::ScenarioBakeOptions{}.texture_scale, nullptr)) {}

CutFaceColours::~CutFaceColours() = default;

std::vector<std::array<double, 3>> CutFaceColours::at(
    const std::vector<core::Vec3>& material_points) const {
  std::vector<std::array<double, 3>> colours(material_points.size());
  for (std::size_t i = 0; i < material_points.size(); ++i) {
    textures::Rgb albedo{};
    float height = 0.0f, wetness = 0.0f;
    texture_->texel(material_points[i], kTexelSize, albedo, height, wetness);
    for (int c = 0; c < 3; ++c)
      colours[i][static_cast<std::size_t>(c)] =
          std::clamp(static_cast<double>(albedo[static_cast<std::size_t>(c)]) / 255.0, 0.0, 1.0);
  }
  return colours;
}

}  // namespace viscera::view
