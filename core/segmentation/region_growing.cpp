#include "core/segmentation/region_growing.h"

#include <cmath>
#include <deque>
#include <string>

#include "core/error.h"
#include "core/segmentation/threshold.h"

namespace viscera::core {

std::array<int, 3> voxel_at(const ImageVolume& volume, const Vec3& p) {
  const Vec3 ijk = volume.spacing.cwiseInverse().asDiagonal() *
                   (volume.direction.inverse() * (p - volume.origin));
  std::array<int, 3> index{};
  for (int a = 0; a < 3; ++a) {
    index[a] = static_cast<int>(std::lround(ijk[a]));
    if (!std::isfinite(ijk[a]) || index[a] < 0 || index[a] >= volume.dims[a]) {
      throw UsageError("point (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ", " +
                       std::to_string(p.z()) + ") m lies outside the volume");
    }
  }
  return index;
}

LabelMap grow_region(const ImageVolume& volume, const std::array<int, 3>& seed, double tolerance,
                     std::uint16_t label) {
  if (!(tolerance >= 0.0)) throw UsageError("region growing tolerance must be 0 or more");
  if (label == 0) throw UsageError("region label must be 1 or more (0 is background)");
  for (int a = 0; a < 3; ++a) {
    if (seed[a] < 0 || seed[a] >= volume.dims[a]) {
      throw UsageError("seed voxel (" + std::to_string(seed[0]) + ", " + std::to_string(seed[1]) +
                       ", " + std::to_string(seed[2]) + ") lies outside the volume");
    }
  }
  LabelMap labels = empty_label_map(volume);
  const auto [nx, ny, nz] = volume.dims;
  const std::size_t start = volume.linear_index(seed[0], seed[1], seed[2]);
  const double reference = volume.value(start);
  std::deque<std::array<int, 3>> queue{seed};
  labels.set_label(start, label);
  static constexpr int kSteps[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                       {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  while (!queue.empty()) {
    const auto [i, j, k] = queue.front();
    queue.pop_front();
    for (const auto& step : kSteps) {
      const int a = i + step[0], b = j + step[1], c = k + step[2];
      if (a < 0 || b < 0 || c < 0 || a >= nx || b >= ny || c >= nz) continue;
      const std::size_t v = volume.linear_index(a, b, c);
      if (labels.label(v) != 0 || std::abs(volume.value(v) - reference) > tolerance) continue;
      labels.set_label(v, label);
      queue.push_back({a, b, c});
    }
  }
  return labels;
}

}  // namespace viscera::core
