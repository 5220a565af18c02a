#pragma once
/// Label maps from intensity windows (DESIGN.md §3: image volume → label map → mesh). Plain
/// functions, deterministic; the label map takes the volume's geometry.

#include <cstdint>
#include <vector>

#include "core/image/image_volume.h"

namespace viscera::core {

/// One intensity window [lower, upper] (inclusive, in the volume's units, e.g. HU) and its label.
struct ThresholdBand {
  double lower = 0.0;
  double upper = 0.0;
  std::uint16_t label = 1;
};

/// An empty (all-background) label map with the geometry of `volume`.
LabelMap empty_label_map(const ImageVolume& volume);

/// Voxels with lower ≤ value ≤ upper get `label`, others 0. Throws UsageError when lower > upper,
/// a bound is NaN or label is 0.
LabelMap threshold(const ImageVolume& volume, double lower, double upper, std::uint16_t label = 1);

/// Several windows at once; a voxel inside several takes the label of the last band listed.
LabelMap multi_threshold(const ImageVolume& volume, const std::vector<ThresholdBand>& bands);

}  // namespace viscera::core
