#!/usr/bin/env bash
# ThreadSanitizer over the project's threads (issue 21 §3), on a build made with
# -fsanitize=thread (./dev.sh tsan configures and builds it in build-tsan/):
#   1. the session loop's unit tests: RealtimeLoop's physics thread driven by a simulated 1 kHz
#      device on its own thread, the triple buffer between them, the UDP bridge;
#   2. a windowed session (Xvfb) with the device emulator sending 1 kHz poses over loopback:
#      HapticDeviceLoop's device thread, the physics thread and the view's render timer;
#   3. the studio's background tasks: the input block, and the main window's and the
#      segmentation panel's real work on worker threads while the UI thread runs its loop.
# Any ThreadSanitizer report ends the step with a non-zero status (halt_on_error).
# Usage: tools/sanitizers/thread_check.sh BUILD_DIR
set -euo pipefail

build="$(cd "$1" && pwd)"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
bin="$build/bin"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:suppressions=$root/tools/sanitizers/tsan.supp"
# libgomp is not instrumented: its barriers look like races to TSan. The flow solver's OpenMP
# loops run on one thread here; every other thread is the project's own.
export OMP_NUM_THREADS=1
display=(xvfb-run -a -s "-screen 0 1280x1024x24 -noreset")

step() { printf '\033[1m==> %s\033[0m\n' "$*" >&2; }

step "session loop unit tests under ThreadSanitizer"
"$bin/viscera_sim_tests" \
  --gtest_filter='TripleBuffer.*:RealtimeLoop.*:UdpDeviceBridge.*:LocalContactModel.*:DevicePackets.*:HapticProxy.*'

step "a windowed session with a 1 kHz UDP device under ThreadSanitizer"
"$bin/viscera" new --template hysteroscopy --seed 1 -o "$work/h.vscene" > /dev/null
port="$(python3 -c 'import socket; s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
# One simulated second takes about 30 s under TSan; the device sends for 15 s of it.
"${display[@]}" "$bin/viscera-sim" run "$work/h.vscene" --width 320 --height 240 --duration 1 \
  --input "udp:$port" --report "$work/report" &
session=$!
"$bin/viscera_device_emulator" --port "$port" --package "$work/h.vscene" --seconds 15 > "$work/device.json"
wait "$session"
python3 - "$work/device.json" <<'PY'
import json, sys
device = json.load(open(sys.argv[1]))
print(f"device: {device['poses_sent']} poses sent, {device['feedback']} feedback packets")
if device["feedback"] == 0:
    sys.exit("thread_check: the device got no feedback, so the device thread did not run")
PY
step "studio background tasks under ThreadSanitizer"
for suite in background gui segmentation; do
  mkdir -p "$work/studio_$suite"
  VISCERA_TEST_TMP="$work/studio_$suite" "${display[@]}" "$bin/viscera_studio_${suite}_tests"
done
step "no ThreadSanitizer report"
