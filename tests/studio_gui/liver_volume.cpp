#include "tests/studio_gui/liver_volume.h"

#include <QtGlobal>
#include <cstdlib>
#include <string>

namespace viscera::studio_tests {

std::filesystem::path cgal_liver(const std::filesystem::path& dir) {
  const std::filesystem::path path = dir / "data/images/liver.inr.gz";
  if (!std::filesystem::exists(path)) {
    const std::string command = "tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz -C '" +
                                dir.string() + "' data/images/liver.inr.gz";
    if (std::system(command.c_str()) != 0) qWarning("%s failed", command.c_str());
  }
  return path;
}

std::array<int, 3> deep_inside(const core::ImageVolume& v, std::array<int, 3> near) {
  std::array<int, 3> best{-1, -1, -1};
  int best_distance = 1 << 30;
  const int k = near[2];
  for (int j = 2; j < v.dims[1] - 2; ++j)
    for (int i = 2; i < v.dims[0] - 2; ++i) {
      bool all = true;
      for (int c = -1; c <= 1 && all; ++c)
        for (int b = -2; b <= 2 && all; ++b)
          for (int a = -2; a <= 2 && all; ++a)
            all = v.value(v.linear_index(i + a, j + b, k + c)) == 255.0;
      const int distance = (i - near[0]) * (i - near[0]) + (j - near[1]) * (j - near[1]);
      if (all && distance < best_distance) {
        best = {i, j, k};
        best_distance = distance;
      }
    }
  return best;
}

}  // namespace viscera::studio_tests
