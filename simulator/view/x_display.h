#pragma once
/// The X display the view renders through (Debian's VTK 9.1 renders through X only,
/// BUILD_NOTES.md). VTK ends the process when it cannot connect to the display; the view asks
/// first, so a missing or refusing display is one clear error and not a crash.

namespace viscera::view {

/// Connects to the display named by DISPLAY and disconnects again. A refused connection is
/// tried again for up to half a second: an X server that is resetting (Xvfb does so when its
/// last client leaves) drops the clients that connect meanwhile. Throws core::UsageError naming
/// the display when DISPLAY is unset or no connection could be made.
void require_x_display();

}  // namespace viscera::view
