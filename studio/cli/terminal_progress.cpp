#include "studio/cli/terminal_progress.h"

#include <unistd.h>

#include <cstdio>

namespace viscera::cli {

TerminalProgress::TerminalProgress()
    : enabled_(isatty(STDERR_FILENO) == 1),
      progress_([this](double fraction, const std::string& stage) { draw(fraction, stage); }) {}

TerminalProgress::~TerminalProgress() {
  if (drawn_) std::fputs("\n", stderr);
}

void TerminalProgress::draw(double fraction, const std::string& stage) {
  if (!enabled_) return;
  constexpr int kWidth = 30;
  const int filled = static_cast<int>(fraction * kWidth + 0.5);
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.append(static_cast<std::size_t>(kWidth - filled), '.');
  std::fprintf(stderr, "\r[%s] %3d%%  %-40.40s", bar.c_str(),
               static_cast<int>(fraction * 100.0 + 0.5), stage.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

}  // namespace viscera::cli
