#include "simulator/view/x_display.h"

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#include "core/error.h"

// Xlib last: its macros (Success, None, …) clash with names declared above.
#include <X11/Xlib.h>

namespace viscera::view {

namespace {
constexpr int kAttempts = 10;
constexpr auto kPause = std::chrono::milliseconds(50);
}  // namespace

void require_x_display() {
  const char* name = std::getenv("DISPLAY");
  if (name == nullptr || *name == '\0')
    throw core::UsageError(
        "rendering needs an X display and DISPLAY is not set: run under xvfb-run, or headless");
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    if (Display* display = XOpenDisplay(name); display != nullptr) {
      XCloseDisplay(display);
      return;
    }
    std::this_thread::sleep_for(kPause);
  }
  throw core::UsageError("cannot connect to the X display '" + std::string(name) +
                         "' that DISPLAY names (tried for half a second)");
}

}  // namespace viscera::view
