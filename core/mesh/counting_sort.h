#pragma once
/// Counting sort by node id: the digit pass of the radix sorts that group mesh elements (tet
/// edges, faces) by their nodes in linear time, where a comparison sort or a tree costs a log
/// factor per element.

#include <cstddef>
#include <vector>

namespace viscera::core {

/// One stable counting-sort pass of `items` by `key_of(item)`, an integer in [0, key_count):
/// items with equal keys keep their order. `scratch` is working room (kept by the caller to
/// reuse its allocation); the sorted items end in `items`.
template <typename Item, typename KeyOf>
void stable_counting_pass(std::vector<Item>& items, std::vector<Item>& scratch, int key_count,
                          KeyOf key_of) {
  std::vector<int> offset(static_cast<std::size_t>(key_count) + 1, 0);
  for (const Item& item : items)
    ++offset[static_cast<std::size_t>(key_of(item)) + 1];
  for (int k = 0; k < key_count; ++k)
    offset[static_cast<std::size_t>(k) + 1] += offset[static_cast<std::size_t>(k)];
  scratch.resize(items.size());
  for (const Item& item : items)
    scratch[static_cast<std::size_t>(offset[static_cast<std::size_t>(key_of(item))]++)] = item;
  items.swap(scratch);
}

}  // namespace viscera::core
