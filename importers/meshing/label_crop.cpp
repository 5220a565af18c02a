#include "importers/meshing/label_crop.h"

#include <algorithm>
#include <cstring>

#include "core/error.h"

namespace viscera::importers {
namespace {

/// Row (j, k) of the map's labels: copied once per row, since the buffer holds bytes.
void read_row(const core::ImageVolume& image, int j, int k, std::vector<std::uint16_t>& row) {
  row.resize(static_cast<std::size_t>(image.dims[0]));
  std::memcpy(row.data(), image.voxels.data() + 2 * image.linear_index(0, j, k), 2 * row.size());
}

}  // namespace

std::vector<int> labels_present(const core::LabelMap& labels) {
  std::vector<char> seen(65536, 0);
  std::vector<std::uint16_t> row;
  for (int k = 0; k < labels.image.dims[2]; ++k)
    for (int j = 0; j < labels.image.dims[1]; ++j) {
      read_row(labels.image, j, k, row);
      for (const std::uint16_t value : row)
        seen[value] = 1;
    }
  std::vector<int> present;
  for (int l = 1; l < 65536; ++l)
    if (seen[static_cast<std::size_t>(l)]) present.push_back(l);
  return present;
}

LabelCrop crop_labels(const core::LabelMap& labels, int label, int padding,
                      const std::string& what) {
  const auto& image = labels.image;
  if (image.voxel_count() == 0 || image.voxels.size() < image.voxel_count() * 2) {
    throw core::InputError("the label map holds no voxels", {what, "", ""});
  }
  if (image.scalar_type != core::ScalarType::UInt16) {
    throw core::InputError("the label map's voxels are " +
                               core::scalar_type_name(image.scalar_type) + ", not uint16 labels",
                           {what, "", ""});
  }
  const auto keep = [label](std::uint16_t value) {
    return label == 0 ? value != 0 : value == label;
  };
  std::array<int, 3> lo{image.dims[0], image.dims[1], image.dims[2]}, hi{-1, -1, -1};
  LabelCrop crop;
  std::vector<std::uint16_t> row;
  for (int k = 0; k < image.dims[2]; ++k)
    for (int j = 0; j < image.dims[1]; ++j) {
      read_row(image, j, k, row);
      for (int i = 0; i < image.dims[0]; ++i) {
        if (!keep(row[static_cast<std::size_t>(i)])) continue;
        ++crop.labelled_voxels;
        lo = {std::min(lo[0], i), std::min(lo[1], j), std::min(lo[2], k)};
        hi = {std::max(hi[0], i), std::max(hi[1], j), std::max(hi[2], k)};
      }
    }
  if (crop.labelled_voxels == 0) {
    throw core::InputError(label == 0
                               ? std::string("the label map is empty: no voxel has a label")
                               : "the label map has no voxel of label " + std::to_string(label),
                           {what, "", ""});
  }
  for (int a = 0; a < 3; ++a) {
    crop.first[a] = lo[a] - padding;
    crop.dims[a] = hi[a] - lo[a] + 1 + 2 * padding;
  }
  crop.labels.assign(static_cast<std::size_t>(crop.dims[0]) * crop.dims[1] * crop.dims[2], 0);
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j) {
      read_row(image, j, k, row);
      const std::size_t out =
          crop.index(lo[0] - crop.first[0], j - crop.first[1], k - crop.first[2]);
      for (int i = lo[0]; i <= hi[0]; ++i) {
        const std::uint16_t value = row[static_cast<std::size_t>(i)];
        if (keep(value)) crop.labels[out + static_cast<std::size_t>(i - lo[0])] = value;
      }
    }
  return crop;
}

core::Vec3 crop_origin(const core::LabelMap& labels, const LabelCrop& crop) {
  return labels.image.index_to_world(core::Vec3(crop.first[0], crop.first[1], crop.first[2]));
}

}  // namespace viscera::importers
