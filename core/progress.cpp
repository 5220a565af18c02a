#include "core/progress.h"

#include <algorithm>

#include "core/error.h"

namespace viscera::core {

void Progress::begin_stage(const std::string& stage, std::int64_t total) {
  stage_ = stage;
  total_.store(std::max<std::int64_t>(total, 1));
  done_.store(0);
  last_reported_permille_.store(-1);
  check_cancelled();
  if (callback_) callback_(0.0, stage_);
}

void Progress::step(std::int64_t units) {
  const std::int64_t done = done_.fetch_add(units) + units;
  check_cancelled();
  if (!callback_) return;
  // Report at most once per permille so a million steps do not flood a terminal.
  const std::int64_t permille = std::min<std::int64_t>(1000, done * 1000 / total_.load());
  std::int64_t last = last_reported_permille_.load();
  if (permille > last && last_reported_permille_.compare_exchange_strong(last, permille)) {
    callback_(static_cast<double>(permille) / 1000.0, stage_);
  }
}

void Progress::check_cancelled() const {
  if (cancelled_.load()) throw CancelledError("cancelled during " + stage_);
}

double Progress::fraction() const noexcept {
  return std::min(1.0, static_cast<double>(done_.load()) / static_cast<double>(total_.load()));
}

Progress& Progress::none() {
  static thread_local Progress silent;
  return silent;
}

}  // namespace viscera::core
