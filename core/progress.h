#pragma once
/// Progress reporting and cooperative cancellation for long operations (meshing, generation,
/// sessions). The CLI draws a bar from the callback; the studio a dialog with Cancel.

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>

namespace viscera::core {

/// Thread-safe progress counter with a cancel flag. Work calls step()/check_cancelled();
/// observers receive (fraction in [0,1], stage name) through the callback.
class Progress {
 public:
  using Callback = std::function<void(double fraction, const std::string& stage)>;

  Progress() = default;
  explicit Progress(Callback callback) : callback_(std::move(callback)) {}

  /// Starts a named stage of `total` units of work and reports 0 for it.
  void begin_stage(const std::string& stage, std::int64_t total);
  /// Adds `units` of finished work; throws CancelledError when cancel() was called.
  void step(std::int64_t units = 1);
  /// Throws CancelledError if cancellation was requested.
  void check_cancelled() const;
  /// Requests cancellation; safe from any thread.
  void cancel() noexcept { cancelled_.store(true); }
  bool cancelled() const noexcept { return cancelled_.load(); }
  /// Fraction of the current stage that is done, in [0, 1].
  double fraction() const noexcept;

  /// A Progress that reports nothing and is never cancelled, for callers that do not care.
  static Progress& none();

 private:
  Callback callback_;
  std::string stage_;
  std::atomic<std::int64_t> done_{0};
  std::atomic<std::int64_t> total_{1};
  std::atomic<std::int64_t> last_reported_permille_{-1};
  std::atomic<bool> cancelled_{false};
};

}  // namespace viscera::core
