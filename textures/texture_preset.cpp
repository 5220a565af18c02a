#include "textures/texture_preset.h"

#include <cmath>

#include "core/error.h"
#include "core/lsystem/lsystem.h"
#include "textures/texture_presets_data.h"

namespace viscera::textures {
namespace {

using nlohmann::json;

[[noreturn]] void invalid(const std::string& pointer, const std::string& message) {
  throw core::ValidationError(message, {"", pointer, ""});
}

double number(const json& j, const char* key, double fallback, double lo, double hi,
              const std::string& pointer) {
  const auto it = j.find(key);
  if (it == j.end()) return fallback;
  const std::string where = pointer + "/" + key;
  if (!it->is_number()) invalid(where, "must be a number");
  const double value = it->get<double>();
  if (!std::isfinite(value) || value < lo || value > hi) {
    invalid(where, "must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
                       std::to_string(value));
  }
  return value;
}

int integer(const json& j, const char* key, int fallback, int lo, int hi,
            const std::string& pointer) {
  const double value = number(j, key, fallback, lo, hi, pointer);
  if (value != std::floor(value)) invalid(pointer + "/" + key, "must be an integer");
  return static_cast<int>(value);
}

Rgb color(const json& j, const char* key, const Rgb& fallback, const std::string& pointer) {
  const auto it = j.find(key);
  if (it == j.end()) return fallback;
  const std::string where = pointer + "/" + key;
  if (!it->is_array() || it->size() != 3) invalid(where, "must be [r, g, b]");
  Rgb c{};
  for (int k = 0; k < 3; ++k) {
    const auto& v = (*it)[k];
    if (!v.is_number() || v.get<double>() < 0.0 || v.get<double>() > 255.0) {
      invalid(where + "/" + std::to_string(k), "must be a number in [0, 255]");
    }
    c[k] = v.get<float>();
  }
  return c;
}

json rgb_json(const Rgb& c) {
  return json::array({c[0], c[1], c[2]});
}

VesselLayerSpec vessel_layer(const json& j, const std::string& p) {
  if (!j.is_object()) invalid(p, "must be an object");
  VesselLayerSpec v;
  const auto grammar = j.find("grammar");
  if (grammar == j.end() || !grammar->is_string()) invalid(p + "/grammar", "must be L-system text");
  v.grammar = grammar->get<std::string>();
  try {
    (void)core::Lsystem::parse(v.grammar, "grammar");
  } catch (const core::InputError& e) {
    invalid(p + "/grammar", e.reason() + " (" + e.location().element + ")");
  }
  v.generations = integer(j, "generations", v.generations, 0, 14, p);
  v.trees = integer(j, "trees", v.trees, 0, 256, p);
  v.step = number(j, "step", v.step, 1e-4, 2.0, p);
  v.width = number(j, "width", v.width, 1e-5, 0.2, p);
  v.angle = number(j, "angle", v.angle, 0.0, 180.0, p);
  v.angle_jitter = number(j, "angle_jitter", v.angle_jitter, 0.0, 90.0, p);
  v.subdivisions = integer(j, "subdivisions", v.subdivisions, 1, 32, p);
  v.wiggle = number(j, "wiggle", v.wiggle, 0.0, 90.0, p);
  v.direction = number(j, "direction", v.direction, -360.0, 360.0, p);
  v.direction_jitter = number(j, "direction_jitter", v.direction_jitter, 0.0, 180.0, p);
  v.taper = number(j, "taper", v.taper, 0.0, 10.0, p);
  v.width_factor = number(j, "width_factor", v.width_factor, 0.0, 1.0, p);
  v.depth_step = number(j, "depth_step", v.depth_step, 0.0, 1.0, p);
  v.color = color(j, "color", v.color, p);
  v.deep_color = color(j, "deep_color", v.deep_color, p);
  v.opacity = number(j, "opacity", v.opacity, 0.0, 1.0, p);
  v.depth_fade = number(j, "depth_fade", v.depth_fade, 0.0, 1.0, p);
  v.height = number(j, "height", v.height, -10.0, 10.0, p);
  v.wetness = number(j, "wetness", v.wetness, -1.0, 1.0, p);
  return v;
}

struct Builtins {
  std::vector<TexturePreset> presets;
};

const Builtins& builtins() {
  static const Builtins instance = [] {
    Builtins b;
    const json document = json::parse(builtin_texture_presets_json());
    const auto& list = document.at("presets");
    for (std::size_t i = 0; i < list.size(); ++i) {
      b.presets.push_back(texture_preset_from_json(list[i], list[i].at("name").get<std::string>(),
                                                   "/presets/" + std::to_string(i)));
    }
    return b;
  }();
  return instance;
}

}  // namespace

TexturePreset texture_preset_from_json(const json& j, const std::string& name,
                                       const std::string& p) {
  if (!j.is_object()) invalid(p, "a preset must be an object");
  TexturePreset t;
  t.name = name;
  t.description = j.value("description", std::string());
  const auto palette = j.find("palette");
  if (palette == j.end() || !palette->is_array() || palette->empty()) {
    invalid(p + "/palette", "must list at least one {color, weight}");
  }
  for (std::size_t i = 0; i < palette->size(); ++i) {
    const std::string entry = p + "/palette/" + std::to_string(i);
    t.palette.push_back(color((*palette)[i], "color", {0, 0, 0}, entry));
    t.palette_weights.push_back(number((*palette)[i], "weight", 1.0, 1e-6, 1e6, entry));
  }
  const json none = json::object();
  const json& field = j.contains("color_field") ? j.at("color_field") : none;
  t.color_frequency =
      number(field, "frequency", t.color_frequency, 0.01, 1024.0, p + "/color_field");
  t.color_octaves = integer(field, "octaves", t.color_octaves, 1, 12, p + "/color_field");
  t.color_persistence =
      number(field, "persistence", t.color_persistence, 0.0, 1.0, p + "/color_field");
  const json& grain = j.contains("grain") ? j.at("grain") : none;
  t.grain_frequency = number(grain, "frequency", t.grain_frequency, 0.01, 4096.0, p + "/grain");
  t.grain_octaves = integer(grain, "octaves", t.grain_octaves, 1, 12, p + "/grain");
  t.grain_persistence = number(grain, "persistence", t.grain_persistence, 0.0, 1.0, p + "/grain");
  t.grain_contrast = number(grain, "contrast", t.grain_contrast, 0.0, 2.0, p + "/grain");
  t.grain_height = number(grain, "height", t.grain_height, -10.0, 10.0, p + "/grain");
  t.grain_aspect = number(grain, "aspect", t.grain_aspect, 0.01, 100.0, p + "/grain");
  t.normal_strength = number(j, "normal_strength", t.normal_strength, 0.0, 10.0, p);
  const json& specular = j.contains("specular") ? j.at("specular") : none;
  t.specular_base = number(specular, "base", t.specular_base, 0.0, 1.0, p + "/specular");
  t.specular_variation =
      number(specular, "variation", t.specular_variation, 0.0, 1.0, p + "/specular");
  t.specular_frequency =
      number(specular, "frequency", t.specular_frequency, 0.01, 1024.0, p + "/specular");
  if (const auto vessels = j.find("vessels"); vessels != j.end()) {
    if (!vessels->is_array()) invalid(p + "/vessels", "must be an array");
    for (std::size_t i = 0; i < vessels->size(); ++i) {
      t.vessels.push_back(vessel_layer((*vessels)[i], p + "/vessels/" + std::to_string(i)));
    }
  }
  return t;
}

json texture_preset_to_json(const TexturePreset& t) {
  json palette = json::array();
  for (std::size_t i = 0; i < t.palette.size(); ++i) {
    palette.push_back({{"color", rgb_json(t.palette[i])}, {"weight", t.palette_weights[i]}});
  }
  json vessels = json::array();
  for (const auto& v : t.vessels) {
    vessels.push_back({{"grammar", v.grammar},
                       {"generations", v.generations},
                       {"trees", v.trees},
                       {"step", v.step},
                       {"width", v.width},
                       {"angle", v.angle},
                       {"angle_jitter", v.angle_jitter},
                       {"subdivisions", v.subdivisions},
                       {"wiggle", v.wiggle},
                       {"direction", v.direction},
                       {"direction_jitter", v.direction_jitter},
                       {"taper", v.taper},
                       {"width_factor", v.width_factor},
                       {"depth_step", v.depth_step},
                       {"color", rgb_json(v.color)},
                       {"deep_color", rgb_json(v.deep_color)},
                       {"opacity", v.opacity},
                       {"depth_fade", v.depth_fade},
                       {"height", v.height},
                       {"wetness", v.wetness}});
  }
  return {{"name", t.name},
          {"description", t.description},
          {"palette", palette},
          {"color_field",
           {{"frequency", t.color_frequency},
            {"octaves", t.color_octaves},
            {"persistence", t.color_persistence}}},
          {"grain",
           {{"frequency", t.grain_frequency},
            {"octaves", t.grain_octaves},
            {"persistence", t.grain_persistence},
            {"contrast", t.grain_contrast},
            {"height", t.grain_height},
            {"aspect", t.grain_aspect}}},
          {"normal_strength", t.normal_strength},
          {"specular",
           {{"base", t.specular_base},
            {"variation", t.specular_variation},
            {"frequency", t.specular_frequency}}},
          {"vessels", vessels}};
}

std::vector<std::string> texture_preset_names() {
  std::vector<std::string> names;
  for (const auto& preset : builtins().presets)
    names.push_back(preset.name);
  return names;
}

const TexturePreset& find_texture_preset(const std::string& name) {
  for (const auto& preset : builtins().presets) {
    if (preset.name == name) return preset;
  }
  std::string known;
  for (const auto& n : texture_preset_names())
    known += (known.empty() ? "" : ", ") + n;
  throw core::UsageError("unknown texture preset \"" + name + "\" (known: " + known + ")");
}

}  // namespace viscera::textures
