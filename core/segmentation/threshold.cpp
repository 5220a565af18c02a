#include "core/segmentation/threshold.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace viscera::core {

LabelMap empty_label_map(const ImageVolume& volume) {
  LabelMap labels;
  labels.image.dims = volume.dims;
  labels.image.spacing = volume.spacing;
  labels.image.origin = volume.origin;
  labels.image.direction = volume.direction;
  labels.image.scalar_type = ScalarType::UInt16;
  labels.image.allocate();
  return labels;
}

LabelMap threshold(const ImageVolume& volume, double lower, double upper, std::uint16_t label) {
  return multi_threshold(volume, {{lower, upper, label}});
}

LabelMap multi_threshold(const ImageVolume& volume, const std::vector<ThresholdBand>& bands) {
  for (const auto& band : bands) {
    if (std::isnan(band.lower) || std::isnan(band.upper) || band.lower > band.upper) {
      throw UsageError("threshold window " + std::to_string(band.lower) + ":" +
                       std::to_string(band.upper) + " is empty or not a number");
    }
    if (band.label == 0) throw UsageError("threshold label must be 1 or more (0 is background)");
  }
  LabelMap labels = empty_label_map(volume);
  const std::size_t n = volume.voxel_count();
  for (std::size_t v = 0; v < n; ++v) {
    const double value = volume.value(v);
    for (const auto& band : bands) {
      if (value >= band.lower && value <= band.upper) labels.set_label(v, band.label);
    }
  }
  return labels;
}

}  // namespace viscera::core
