#!/bin/sh
# Runs a program that renders: as is when an X display is set, otherwise under a private Xvfb
# server (Debian's VTK 9.1 renders through X only, BUILD_NOTES.md). Used as the test
# executables' CROSSCOMPILING_EMULATOR, so ctest runs the rendering tests anywhere.
if [ -n "${DISPLAY:-}" ]; then
  exec "$@"
fi
# -noreset: Xvfb would otherwise reset when its last client leaves and drop one joining meanwhile.
exec xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$@"
