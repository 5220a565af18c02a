#pragma once
/// The part of a label map that meshing works on: the voxels of the chosen labels inside their
/// bounding box, padded with background so that every surface closes inside the box.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/image/image_volume.h"

namespace viscera::importers {

/// A box of a label map in voxel indices with copies of its labels (x fastest).
struct LabelCrop {
  std::array<int, 3> first{0, 0, 0};  ///< voxel index of the box's corner in the full map
  std::array<int, 3> dims{0, 0, 0};   ///< box size in voxels, padding included
  std::vector<std::uint16_t> labels;  ///< kept labels, 0 elsewhere (and in the padding)
  std::size_t labelled_voxels = 0;    ///< voxels holding a kept label

  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * dims[1] + j) * dims[0] + i;
  }
};

/// The labels other than 0 that occur in `labels`, ascending.
std::vector<int> labels_present(const core::LabelMap& labels);

/// Copies the voxels of `label` (every label other than 0 when `label` is 0) inside their
/// bounding box, grown by `padding` voxels of background on each side; voxels of other labels
/// become 0. Throws core::InputError naming `what` when the map has no voxels, no labelled
/// voxel, or no voxel of `label`.
LabelCrop crop_labels(const core::LabelMap& labels, int label, int padding,
                      const std::string& what);

/// World position in m of the corner of the crop's voxel (0,0,0) — the centre of the full map's
/// voxel `crop.first` — used to place meshes made in the crop's own frame.
core::Vec3 crop_origin(const core::LabelMap& labels, const LabelCrop& crop);

}  // namespace viscera::importers
