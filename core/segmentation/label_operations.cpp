#include "core/segmentation/label_operations.h"

#include <algorithm>
#include <string>

#include "core/error.h"

namespace viscera::core {

std::map<std::uint16_t, std::size_t> label_counts(const LabelMap& labels) {
  std::map<std::uint16_t, std::size_t> counts;
  for (std::size_t v = 0; v < labels.image.voxel_count(); ++v)
    if (const auto label = labels.label(v); label != 0) ++counts[label];
  return counts;
}

LabelMap keep_largest_component(const LabelMap& labels) {
  const auto [nx, ny, nz] = labels.image.dims;
  const std::size_t n = labels.image.voxel_count();
  std::vector<int> component(n, -1);
  std::vector<std::size_t> sizes;
  std::vector<std::uint16_t> component_label;
  std::vector<std::size_t> stack;
  for (std::size_t start = 0; start < n; ++start) {
    const std::uint16_t label = labels.label(start);
    if (label == 0 || component[start] >= 0) continue;
    const int id = static_cast<int>(sizes.size());
    sizes.push_back(0);
    component_label.push_back(label);
    component[start] = id;
    stack.assign(1, start);
    while (!stack.empty()) {
      const std::size_t v = stack.back();
      stack.pop_back();
      ++sizes[id];
      const int i = static_cast<int>(v % nx), j = static_cast<int>((v / nx) % ny),
                k = static_cast<int>(v / (static_cast<std::size_t>(nx) * ny));
      const int neighbours[6][3] = {{i + 1, j, k}, {i - 1, j, k}, {i, j + 1, k},
                                    {i, j - 1, k}, {i, j, k + 1}, {i, j, k - 1}};
      for (const auto& [a, b, c] : neighbours) {
        if (a < 0 || b < 0 || c < 0 || a >= nx || b >= ny || c >= nz) continue;
        const std::size_t w = labels.image.linear_index(a, b, c);
        if (component[w] < 0 && labels.label(w) == label) {
          component[w] = id;
          stack.push_back(w);
        }
      }
    }
  }
  std::map<std::uint16_t, int> largest;
  for (int id = 0; id < static_cast<int>(sizes.size()); ++id) {
    auto [it, inserted] = largest.try_emplace(component_label[id], id);
    if (!inserted && sizes[id] > sizes[it->second]) it->second = id;
  }
  LabelMap out = labels;
  for (std::size_t v = 0; v < n; ++v) {
    if (component[v] >= 0 && largest[labels.label(v)] != component[v]) out.set_label(v, 0);
  }
  return out;
}

LabelMap merge_labels(const LabelMap& labels, const std::vector<std::uint16_t>& from,
                      std::uint16_t to) {
  LabelMap out = labels;
  for (std::size_t v = 0; v < labels.image.voxel_count(); ++v) {
    if (std::find(from.begin(), from.end(), labels.label(v)) != from.end()) out.set_label(v, to);
  }
  for (const auto label : from) {
    if (label != to) out.names.erase(label);
  }
  return out;
}

LabelMap remove_label(const LabelMap& labels, std::uint16_t label) {
  return merge_labels(labels, {label}, 0);
}

LabelMap relabel(const LabelMap& labels, std::uint16_t from, std::uint16_t to) {
  if (from != to && label_counts(labels).count(to) != 0) {
    throw UsageError("label " + std::to_string(to) + " is already used; merge the labels instead");
  }
  LabelMap out = merge_labels(labels, {from}, to);
  if (const auto name = labels.names.find(from); name != labels.names.end() && to != 0) {
    out.names[to] = name->second;
  }
  return out;
}

}  // namespace viscera::core
