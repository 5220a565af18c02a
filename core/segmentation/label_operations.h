#pragma once
/// Connected components and label arithmetic on label maps. Components are 6-connected (voxels
/// sharing a face), the connectivity the mesher's surfaces follow. Label names travel with
/// their labels.

#include <cstdint>
#include <map>
#include <vector>

#include "core/image/image_volume.h"

namespace viscera::core {

/// Voxel count of every non-zero label.
std::map<std::uint16_t, std::size_t> label_counts(const LabelMap& labels);

/// Keeps, for each non-zero label, only its largest 6-connected component (ties: the one met
/// first in x-fastest order); the other components become background.
LabelMap keep_largest_component(const LabelMap& labels);

/// Labels in `from` become `to` (to may be 0: removal). Names of removed labels are dropped.
LabelMap merge_labels(const LabelMap& labels, const std::vector<std::uint16_t>& from,
                      std::uint16_t to);

/// Label `label` becomes background.
LabelMap remove_label(const LabelMap& labels, std::uint16_t label);

/// Label `from` becomes `to`; throws UsageError when `to` is already used (use merge_labels).
LabelMap relabel(const LabelMap& labels, std::uint16_t from, std::uint16_t to);

}  // namespace viscera::core
