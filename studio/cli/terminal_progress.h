#pragma once
/// A progress bar on standard error when it is a terminal; silent otherwise, so pipes and
/// --json output stay clean.

#include <string>

#include "core/progress.h"

namespace viscera::cli {

/// A core::Progress whose callback redraws one terminal line: "[#####.....]  45%  stage".
class TerminalProgress {
 public:
  TerminalProgress();
  ~TerminalProgress();
  TerminalProgress(const TerminalProgress&) = delete;
  TerminalProgress& operator=(const TerminalProgress&) = delete;

  core::Progress& progress() { return progress_; }

 private:
  void draw(double fraction, const std::string& stage);

  bool enabled_ = false;
  bool drawn_ = false;
  core::Progress progress_;
};

}  // namespace viscera::cli
