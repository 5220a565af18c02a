#pragma once
// A haptic device emulator on the loopback interface (issue 16 item 3), the test tool behind
// `viscera_device_emulator`, the window feedback benchmark and the threaded-session tests: one
// thread sends pose packets at a fixed rate (1 kHz, on absolute deadlines), another receives
// the simulator's feedback, each packet timed by the kernel on arrival (SO_TIMESTAMPNS), so the
// feedback rate and the gaps between feedback packets (their percentiles) are measured as the
// device's controller would see them, whatever the emulator's own threads' scheduling. Both
// threads ask for a real-time priority as a device's servo loop runs (best effort).

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "simulator/haptics/device_packets.h"
#include "simulator/session/instrument_state.h"

namespace viscera::testing {

/// What the emulator measured. Times in s, force in N.
struct EmulatorReport {
  long long poses_sent = 0;
  long long feedback = 0;      ///< feedback packets received (valid ones)
  double feedback_rate = 0.0;  ///< packets per second from the first to the last feedback
  double gap_p50 = 0.0, gap_p90 = 0.0, gap_p99 = 0.0, gap_max = 0.0;  ///< between packets
  double max_force = 0.0;                                             ///< largest |force| fed back
};

/// The pose to send at `t` s after the start; the emulator fills sequence and time.
using PosePath = std::function<sim::DevicePose(double t)>;

/// The pose of an instrument state: position = tip, orientation turning the rest frame (shaft
/// +z, up +y) onto state.axis and state.up (the inverse of sim::instrument_from_pose).
sim::DevicePose pose_of(const sim::InstrumentState& state);

/// Runs the emulator against a bridge on 127.0.0.1:`port` for `seconds` s (or until `stop`
/// becomes true), sending `path`'s pose `rate` times a second.
EmulatorReport emulate_device(std::uint16_t port, double seconds, const PosePath& path,
                              double rate = 1000.0, const std::atomic<bool>* stop = nullptr);

/// `q`-quantile (0…1) of `values` (sorted in place), by the nearest rank.
double quantile(std::vector<double>& values, double q);

}  // namespace viscera::testing
