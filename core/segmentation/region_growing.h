#pragma once
/// Region growing from a seed voxel: the 6-connected set of voxels reachable from the seed
/// through voxels whose value lies within `tolerance` of the seed's value. Breadth-first, so
/// the result does not depend on visiting order.

#include <array>
#include <cstdint>

#include "core/image/image_volume.h"

namespace viscera::core {

/// Voxel index (i, j, k) of the voxel centre nearest to world point `p` (m); throws UsageError
/// naming the point when it lies outside the volume.
std::array<int, 3> voxel_at(const ImageVolume& volume, const Vec3& p);

/// The grown region labelled `label` (others 0). Throws UsageError when the seed is outside,
/// tolerance is negative or NaN, or label is 0.
LabelMap grow_region(const ImageVolume& volume, const std::array<int, 3>& seed, double tolerance,
                     std::uint16_t label = 1);

}  // namespace viscera::core
