#pragma once
/// Block-average downsampling of an image volume: a coarser working copy for interactive
/// segmentation and coarse meshing (issue 9 §4; 3D Slicer's "Resample scalar volume" with an
/// integer factor). Deterministic; the geometry stays in the same world frame.

#include <array>

#include "core/image/image_volume.h"

namespace viscera::core {

/// The volume with `factors` (i, j, k) voxels merged into one: dims ⌊d / f⌋ (the remainder
/// voxels at the high end of each axis are dropped), spacing × f, each new voxel the mean of its
/// block, rounded to nearest for integer scalar types, and its centre at the block's centre
/// (origin = world position of index ((f − 1) / 2, …)). Same scalar type and direction.
/// Throws UsageError when a factor is < 1 or larger than the volume's size along its axis.
ImageVolume downsample(const ImageVolume& volume, const std::array<int, 3>& factors);

}  // namespace viscera::core
