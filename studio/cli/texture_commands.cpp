#include "studio/cli/texture_commands.h"

#include <cstdio>

#include "studio/cli/command_output.h"
#include "textures/perlin_noise.h"

namespace viscera::cli {

void add_texture_commands(CLI::App& app) {
  auto* noise = app.add_subcommand("noise", "Perlin improved noise at a point (17 significant digits)");
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
}

}  // namespace viscera::cli
