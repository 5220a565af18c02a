#pragma once
/// A time series a session report keeps (energy samples, the instrument path, replay
/// checkpoints), held within a fixed number of entries however long the session runs
/// (issue 21 §4: an hour's report must not cost more memory than ten minutes').
///
/// The caller offers every sample it takes, numbered at its base rate (0, 1, 2, …). The series
/// stores those whose number is a multiple of the current stride. When it is full, every other
/// entry is dropped and the stride doubles, so the series always covers the whole session,
/// evenly, at a resolution that halves each time the capacity is reached. The rule depends only
/// on the sample numbers: a replay thins its checkpoints exactly as the recording did.

#include <cstddef>
#include <vector>

namespace viscera::sim {

class SeriesThinning {
 public:
  /// `capacity` ≥ 2 entries.
  explicit SeriesThinning(std::size_t capacity) : capacity_(capacity < 2 ? 2 : capacity) {}

  /// True when sample number `index` (base rate) belongs in the series at the current stride.
  bool due(long long index) const { return index % stride_ == 0; }

  /// Stores `value` (sample number `index`) when it is due; thins the series first when it is
  /// full. A value that is not due is dropped, unless `always` (the session's last sample).
  template <class T>
  void offer(std::vector<T>& series, long long index, T value, bool always = false) {
    if (!always && !due(index)) return;
    if (series.size() >= capacity_) {
      // Entries sit at multiples of the stride from sample 0: the even positions are the
      // multiples of twice the stride.
      std::size_t kept = 0;
      for (std::size_t i = 0; i < series.size(); i += 2)
        series[kept++] = std::move(series[i]);
      series.resize(kept);
      stride_ *= 2;
      if (!always && !due(index)) return;
    }
    series.push_back(std::move(value));
  }

  /// Base-rate samples between two stored entries now.
  long long stride() const { return stride_; }
  std::size_t capacity() const { return capacity_; }

 private:
  std::size_t capacity_;
  long long stride_ = 1;
};

}  // namespace viscera::sim
