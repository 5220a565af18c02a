#include "studio/cli/model_files.h"

#include <cmath>
#include <sstream>

#include "core/error.h"
#include "studio/cli/cli_files.h"
#include "textures/png_io.h"

namespace viscera::cli {

core::ModelDocument load_model(const std::string& path) {
  return core::model_from_json(read_json_file(path), path);
}

void save_model(const core::ModelDocument& model, const std::string& path) {
  core::check_model(model);
  textures::write_file_atomically(core::model_to_json(model).dump(2) + "\n", path);
}

core::Vec3 parse_point(const std::string& text, const std::string& option) {
  std::istringstream in(text);
  core::Vec3 p;
  char comma1 = 0, comma2 = 0;
  in >> p.x() >> comma1 >> p.y() >> comma2 >> p.z();
  if (!in || comma1 != ',' || comma2 != ',' || !(in >> std::ws).eof() || !p.allFinite())
    throw core::UsageError(option + " expects x,y,z in m, got \"" + text + "\"");
  return p;
}

std::vector<core::Vec3> parse_points(const std::vector<std::string>& texts,
                                     const std::string& option) {
  std::vector<core::Vec3> points;
  for (const auto& text : texts)
    points.push_back(parse_point(text, option));
  return points;
}

}  // namespace viscera::cli
