#pragma once
/// Tissue texture presets: the parameters of texture_synthesis.h as data. The built-in presets
/// live in data/textures/presets.json (compiled in) so a clinician-engineer can tune them without
/// touching code; their colours come from endoscopic appearance (seed 001 §3.3, seed 000 §7).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "textures/sample_noise_field.h"

namespace viscera::textures {

/// One layer of vessels painted with an L-system (seed 001 §3.3). Lengths are fractions of the
/// texture width so a preset looks the same at every resolution.
struct VesselLayerSpec {
  std::string grammar;  ///< L-system text (core/lsystem/lsystem.h)
  int generations = 5;
  int trees = 3;                         ///< trees per texture
  double step = 0.05;                    ///< F length without a parameter, texture widths
  double width = 0.004;                  ///< initial stroke width, texture widths
  double angle = 25.0;                   ///< degrees
  double angle_jitter = 10.0;            ///< degrees
  int subdivisions = 3;                  ///< pieces per F, each turning by up to ± wiggle
  double wiggle = 8.0;                   ///< degrees: tortuosity of the vessels
  double direction = 90.0;               ///< degrees from the +u axis of each tree's first segment
  double direction_jitter = 180.0;       ///< degrees; 180 = any direction
  double taper = 0.0;                    ///< width lost per texture width drawn (relative)
  double width_factor = 0.7;             ///< width factor of `!`
  double depth_step = 0.15;              ///< depth increment of `'`
  Rgb color{150.0f, 20.0f, 30.0f};       ///< vessel at the surface
  Rgb deep_color{120.0f, 60.0f, 90.0f};  ///< vessel at depth 1 (bluish, seen through tissue)
  double opacity = 0.85;                 ///< at the surface
  double depth_fade = 0.8;               ///< opacity lost at depth 1
  double height = 0.5;                   ///< bump height of a superficial vessel (height units)
  double wetness = 0.1;                  ///< added specular over a vessel
};

/// Every parameter of one tissue texture.
struct TexturePreset {
  std::string name;
  std::string description;
  std::vector<Rgb> palette;  ///< used when no sample image is given
  std::vector<double> palette_weights;
  double color_frequency = 6.0;  ///< lattice cells per texture width of the colour field
  int color_octaves = 3;
  double color_persistence = 0.5;
  double grain_frequency = 24.0;  ///< Perlin cells per texture width
  int grain_octaves = 4;
  double grain_persistence = 0.5;
  double grain_contrast = 0.3;  ///< brightness change per unit of normalised turbulence
  double grain_height = 1.0;    ///< height of normalised turbulence (height units)
  double grain_aspect = 1.0;  ///< frequency factor along v: < 1 stretches grain into folds along v
  double normal_strength =
      0.02;  ///< k in n = normalise(−k ∂h/∂u, −k ∂h/∂v, 1), u in texture widths
  double specular_base = 0.5;  ///< wetness in [0, 1]
  double specular_variation = 0.2;
  double specular_frequency = 5.0;
  std::vector<VesselLayerSpec> vessels;  ///< painted deep layers first
};

/// Parses and checks a preset; throws core::ValidationError with the JSON pointer (under
/// `pointer`) of the first bad member.
TexturePreset texture_preset_from_json(const nlohmann::json& json, const std::string& name,
                                       const std::string& pointer = "");
nlohmann::json texture_preset_to_json(const TexturePreset& preset);

/// Names of the built-in presets, in the order of presets.json.
std::vector<std::string> texture_preset_names();
/// The built-in preset `name`; throws core::UsageError listing the names otherwise.
const TexturePreset& find_texture_preset(const std::string& name);

}  // namespace viscera::textures
