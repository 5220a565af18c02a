#pragma once
/// Lock-free exchange of the latest value between one writer thread and one reader thread
/// (DESIGN.md §5: threads exchange snapshots, never locks in the hot path). Three slots: the
/// writer fills its own, then swaps it with the shared middle slot and marks it fresh; the
/// reader swaps the middle slot with its own only when it is fresh. Neither ever waits.

#include <array>
#include <atomic>
#include <cstdint>

namespace viscera::sim {

template <typename T>
class TripleBuffer {
 public:
  /// The writer's slot: fill it, then publish().
  T& write_slot() { return slots_[writer_]; }

  /// Hands the writer's slot to the reader side and takes the old middle slot to write next.
  void publish() {
    const std::uint8_t previous =
        middle_.exchange(static_cast<std::uint8_t>(writer_ | kFresh), std::memory_order_acq_rel);
    writer_ = previous & kIndex;
  }

  /// Takes the newest published value if there is one; returns whether it changed.
  bool update() {
    if ((middle_.load(std::memory_order_relaxed) & kFresh) == 0) return false;
    const std::uint8_t previous = middle_.exchange(reader_, std::memory_order_acq_rel);
    reader_ = previous & kIndex;
    return true;
  }

  /// The reader's current value (the newest as of the last update()).
  const T& read_slot() const { return slots_[reader_]; }

 private:
  static constexpr std::uint8_t kIndex = 0x3, kFresh = 0x4;
  std::array<T, 3> slots_{};
  std::uint8_t writer_ = 0;
  std::uint8_t reader_ = 1;
  std::atomic<std::uint8_t> middle_{2};
};

}  // namespace viscera::sim
