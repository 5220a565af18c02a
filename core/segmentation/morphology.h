#pragma once
/// Morphological opening and closing of a label map with a ball of `radius` voxels (offsets d
/// with |d|² ≤ radius²; radius 1 is the 6-neighbourhood). Each label is treated as its own
/// binary mask; voxels outside the volume count as background. Opening removes specks and thin
/// bridges thinner than the ball; closing fills gaps and holes smaller than it, taking only
/// background voxels (a closing never overwrites another label).

#include <cstdint>

#include "core/image/image_volume.h"

namespace viscera::core {

/// Erosion then dilation of every label. Throws UsageError for radius < 1.
LabelMap open_labels(const LabelMap& labels, int radius);

/// Dilation then erosion of every label. Throws UsageError for radius < 1.
LabelMap close_labels(const LabelMap& labels, int radius);

}  // namespace viscera::core
