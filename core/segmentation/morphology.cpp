#include "core/segmentation/morphology.h"

#include <array>
#include <set>
#include <vector>

#include "core/error.h"

namespace viscera::core {
namespace {

using Offsets = std::vector<std::array<int, 3>>;

Offsets ball(int radius) {
  if (radius < 1) throw UsageError("morphology radius must be 1 voxel or more");
  Offsets offsets;
  for (int k = -radius; k <= radius; ++k)
    for (int j = -radius; j <= radius; ++j)
      for (int i = -radius; i <= radius; ++i)
        if (i * i + j * j + k * k <= radius * radius) offsets.push_back({i, j, k});
  return offsets;
}

/// Erosion (all offsets inside) or dilation (any offset inside) of a binary mask.
std::vector<char> apply(const std::vector<char>& mask, const std::array<int, 3>& dims,
                        const Offsets& offsets, bool erode) {
  std::vector<char> out(mask.size(), 0);
  const auto [nx, ny, nz] = dims;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        bool result = erode;
        for (const auto& d : offsets) {
          const int a = i + d[0], b = j + d[1], c = k + d[2];
          const bool inside = a >= 0 && b >= 0 && c >= 0 && a < nx && b < ny && c < nz &&
                              mask[(static_cast<std::size_t>(c) * ny + b) * nx + a] != 0;
          if (erode && !inside) {
            result = false;
            break;
          }
          if (!erode && inside) {
            result = true;
            break;
          }
        }
        out[(static_cast<std::size_t>(k) * ny + j) * nx + i] = result ? 1 : 0;
      }
  return out;
}

LabelMap morph(const LabelMap& labels, int radius, bool opening) {
  const Offsets offsets = ball(radius);
  const std::size_t n = labels.image.voxel_count();
  std::set<std::uint16_t> present;
  for (std::size_t v = 0; v < n; ++v)
    if (labels.label(v) != 0) present.insert(labels.label(v));
  LabelMap out = labels;
  for (const std::uint16_t label : present) {
    std::vector<char> mask(n);
    for (std::size_t v = 0; v < n; ++v)
      mask[v] = labels.label(v) == label ? 1 : 0;
    const auto first = apply(mask, labels.image.dims, offsets, opening);
    const auto result = apply(first, labels.image.dims, offsets, !opening);
    for (std::size_t v = 0; v < n; ++v) {
      if (opening && mask[v] && !result[v]) out.set_label(v, 0);
      if (!opening && !mask[v] && result[v] && labels.label(v) == 0) out.set_label(v, label);
    }
  }
  return out;
}

}  // namespace

LabelMap open_labels(const LabelMap& labels, int radius) {
  return morph(labels, radius, true);
}

LabelMap close_labels(const LabelMap& labels, int radius) {
  return morph(labels, radius, false);
}

}  // namespace viscera::core
