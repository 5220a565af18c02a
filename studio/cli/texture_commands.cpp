#include "studio/cli/texture_commands.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "core/error.h"
#include "core/package/scenario_package.h"
#include "studio/cli/command_output.h"
#include "studio/cli/terminal_progress.h"
#include "textures/perlin_noise.h"
#include "textures/png_io.h"
#include "textures/scenario_baking.h"
#include "textures/texture_preset.h"
#include "textures/texture_synthesis.h"

namespace viscera::cli {
namespace {

struct TextureCommandOptions {
  std::string preset;
  std::uint64_t seed = 1;
  std::string size = "1024x1024";
  std::string sample;
  std::string output;
  bool all_maps = false;
  bool no_vessels = false;
  bool list = false;
  bool json = false;
};

/// "WxH" or "N" (square) → pixels; throws UsageError otherwise.
std::pair<int, int> parse_size(const std::string& text) {
  const auto x = text.find('x');
  try {
    std::size_t used = 0;
    const int width = std::stoi(text.substr(0, x), &used);
    if (used != text.substr(0, x).size()) throw std::invalid_argument(text);
    int height = width;
    if (x != std::string::npos) {
      const std::string rest = text.substr(x + 1);
      height = std::stoi(rest, &used);
      if (used != rest.size()) throw std::invalid_argument(text);
    }
    return {width, height};
  } catch (const std::logic_error&) {
    throw core::UsageError("--size expects WxH in pixels, e.g. 1024x1024, got \"" + text + "\"");
  }
}

/// OUT.png → OUT_<suffix>.png beside it.
std::filesystem::path sibling_map(const std::filesystem::path& output, const std::string& suffix) {
  return output.parent_path() /
         (output.stem().string() + "_" + suffix + output.extension().string());
}

void list_presets(bool json) {
  nlohmann::json presets = nlohmann::json::array();
  std::string text;
  for (const auto& name : textures::texture_preset_names()) {
    const auto& preset = textures::find_texture_preset(name);
    presets.push_back(textures::texture_preset_to_json(preset));
    text += name + "\n  " + preset.description + "\n";
  }
  if (json) {
    print_json(presets);
  } else {
    print_text(text);
  }
}

void make_texture(const TextureCommandOptions& o) {
  if (o.list) return list_presets(o.json);
  if (o.preset.empty()) throw core::UsageError("--preset is required (see --list)");
  if (o.output.empty()) throw core::UsageError("-o OUT.png is required");
  const auto& preset = textures::find_texture_preset(o.preset);
  const auto [width, height] = parse_size(o.size);
  std::optional<textures::Image8> sample;
  if (!o.sample.empty()) sample = textures::read_image_rgb(o.sample);

  textures::TextureOptions options;
  options.seed = o.seed;
  options.width = width;
  options.height = height;
  options.sample = sample ? &*sample : nullptr;
  options.vessels = !o.no_vessels;
  options.normal_and_specular = o.all_maps;
  TerminalProgress bar;
  const textures::TextureMaps maps = textures::synthesize_texture(preset, options, bar.progress());

  // Encode everything before writing anything, so an encoding failure leaves no file behind.
  const std::filesystem::path output = o.output;
  std::vector<std::pair<std::filesystem::path, std::string>> files = {
      {output, textures::encode_png(maps.albedo)}};
  if (o.all_maps) {
    files.emplace_back(sibling_map(output, "normal"), textures::encode_png(maps.normal));
    files.emplace_back(sibling_map(output, "specular"), textures::encode_png(maps.specular));
  }
  nlohmann::json written = nlohmann::json::array();
  for (const auto& [path, bytes] : files) {
    textures::write_file_atomically(bytes, path);
    written.push_back(std::filesystem::absolute(path).string());
  }
  if (o.json) {
    print_json({{"preset", o.preset},
                {"seed", o.seed},
                {"width", width},
                {"height", height},
                {"sample", o.sample},
                {"files", written}});
  } else {
    std::string text;
    for (const auto& path : written)
      text += "wrote " + path.get<std::string>() + "\n";
    print_text(text);
  }
}

struct BakeCommandOptions {
  std::string input, output, preset, size = "1024x1024", sample;
  std::vector<std::string> objects;
  std::uint64_t seed = 1;
  double scale = 0.05;
  bool keep_topology = false, json = false;
};

const char* mapping_name(textures::TextureMapping mapping) {
  switch (mapping) {
    case textures::TextureMapping::OwnUvs:
      return "own-uvs";
    case textures::TextureMapping::Atlas:
      return "lscm-atlas";
    case textures::TextureMapping::VertexColors:
      return "vertex-colors";
  }
  return "?";
}

void bake(const BakeCommandOptions& o) {
  const auto [width, height] = parse_size(o.size);
  std::optional<textures::Image8> sample;
  if (!o.sample.empty()) sample = textures::read_image_rgb(o.sample);
  TerminalProgress bar;
  core::Scenario scenario = core::read_package(o.input, bar.progress());
  if (!o.preset.empty()) {
    (void)textures::find_texture_preset(o.preset);  // a usage error before any work
    int assigned = 0;
    for (auto& object : scenario.objects) {
      const bool chosen = o.objects.empty() ? object.role == core::ObjectRole::Organ
                                            : std::find(o.objects.begin(), o.objects.end(),
                                                        object.id) != o.objects.end();
      if (!chosen) continue;
      core::TextureSpec spec;
      spec.id = object.id + "-" + o.preset;
      spec.preset = o.preset;
      spec.seed = o.seed;
      spec.width = width;
      spec.height = height;
      scenario.textures[spec.id] = spec;
      object.texture = spec.id;
      ++assigned;
    }
    if (assigned == 0) throw core::UsageError("no object of the package matches --object");
  }
  textures::ScenarioBakeOptions options;
  options.texture_scale = o.scale;
  options.sample = sample ? &*sample : nullptr;
  options.keep_topology = o.keep_topology;
  const textures::BakedTextures baked =
      textures::bake_textures_into(scenario, options, bar.progress());
  if (baked.objects.empty())
    throw core::UsageError("nothing to bake: no object has a texture (use --preset)");
  core::write_package(scenario, baked.files, o.output, bar.progress());

  nlohmann::json objects = nlohmann::json::array();
  std::string text = "wrote " + std::filesystem::absolute(o.output).string() + "\n";
  for (const auto& b : baked.objects) {
    objects.push_back({{"object", b.object},
                       {"texture", b.texture},
                       {"mapping", mapping_name(b.mapping)},
                       {"charts", b.charts},
                       {"l2_stretch", b.distortion.l2_stretch},
                       {"mean_conformal", b.distortion.mean_conformal},
                       {"maps", scenario.textures.at(b.texture).maps}});
    char line[256];
    std::snprintf(line, sizeof line, "  %s: %s, %s, %d charts, L2 stretch %.3f\n", b.object.c_str(),
                  b.texture.c_str(), mapping_name(b.mapping), b.charts, b.distortion.l2_stretch);
    text += line;
  }
  if (o.json) {
    print_json({{"package", std::filesystem::absolute(o.output).string()}, {"objects", objects}});
  } else {
    print_text(text);
  }
}

}  // namespace

void add_texture_commands(CLI::App& app) {
  auto* noise =
      app.add_subcommand("noise", "Perlin improved noise at a point (17 significant digits)");
  auto point = std::make_shared<std::array<double, 3>>();
  auto json = std::make_shared<bool>(false);
  noise->add_option("x", (*point)[0], "x")->required();
  noise->add_option("y", (*point)[1], "y")->required();
  noise->add_option("z", (*point)[2], "z")->required();
  noise->add_flag("--json", *json, "Print JSON");
  noise->callback([point, json] {
    const double value = textures::PerlinNoise().noise((*point)[0], (*point)[1], (*point)[2]);
    if (*json) {
      print_json({{"x", (*point)[0]}, {"y", (*point)[1]}, {"z", (*point)[2]}, {"noise", value}});
    } else {
      char text[40];
      std::snprintf(text, sizeof text, "%.17g\n", value);
      print_text(text);
    }
  });

  auto* texture = app.add_subcommand(
      "texture", "Synthesise a tissue texture (albedo PNG; --maps adds normal and specular)");
  auto options = std::make_shared<TextureCommandOptions>();
  texture->add_option("--preset,-p", options->preset,
                      "Preset: endometrium, myoma-surface, peritoneum, liver, urethral-mucosa");
  texture->add_option("--seed", options->seed, "Random seed")->capture_default_str();
  texture->add_option("--size", options->size, "Size in pixels, WxH")->capture_default_str();
  texture->add_option(
      "--sample", options->sample,
      "Sample image whose pixels fill the noise lattice (KisMo), instead of the preset palette");
  texture->add_option("-o,--output", options->output, "Output PNG (albedo)");
  texture->add_flag("--maps", options->all_maps, "Also write OUT_normal.png and OUT_specular.png");
  texture->add_flag("--no-vessels", options->no_vessels, "Leave out the vessel layers");
  texture->add_flag("--list", options->list, "List the presets and their parameters");
  texture->add_flag("--json", options->json, "Print JSON");
  texture->callback([options] { make_texture(*options); });

  auto* baking = app.add_subcommand(
      "bake", "Bake procedural textures onto a package's organs (LSCM atlas, maps in textures/)");
  auto b = std::make_shared<BakeCommandOptions>();
  baking->add_option("input", b->input, "Input package (.vscene or .vscz)")->required();
  baking->add_option("-o,--output", b->output, "Output package")->required();
  baking->add_option("--preset,-p", b->preset,
                     "Give the objects this preset (else bake their own textures)");
  baking->add_option("--object", b->objects,
                     "Objects to texture with --preset (default: every organ)");
  baking->add_option("--seed", b->seed, "Texture seed with --preset")->capture_default_str();
  baking->add_option("--size", b->size, "Map size in pixels, WxH, with --preset")
      ->capture_default_str();
  baking->add_option("--sample", b->sample, "Sample image for the colour field (KisMo)");
  baking->add_option("--scale", b->scale, "Metres of surface per texture width")
      ->capture_default_str();
  baking->add_flag("--keep-topology", b->keep_topology,
                   "Never split seam vertices: surfaces without UVs get vertex colours instead");
  baking->add_flag("--json", b->json, "Print JSON");
  baking->callback([b] { bake(*b); });
}

}  // namespace viscera::cli
