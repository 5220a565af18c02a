#include "tests/bench/device_emulator.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include "simulator/haptics/simulated_device.h"

namespace viscera::testing {

sim::DevicePose pose_of(const sim::InstrumentState& state) {
  const core::Vec3 axis = state.axis.normalized();
  const core::Vec3 up = (state.up - state.up.dot(axis) * axis).normalized();
  Eigen::Matrix3d frame;
  frame.col(0) = up.cross(axis);
  frame.col(1) = up;
  frame.col(2) = axis;
  const Eigen::Quaterniond q(frame);
  sim::DevicePose pose;
  pose.position = state.tip;
  pose.orientation = {q.w(), q.x(), q.y(), q.z()};
  pose.inflow_valve = static_cast<float>(state.inflow);
  pose.outflow_valve = static_cast<float>(state.outflow);
  return pose;
}

double quantile(std::vector<double>& values, double q) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(values.size())));
  return values[std::min(values.size() - 1, rank == 0 ? 0 : rank - 1)];
}

EmulatorReport emulate_device(std::uint16_t port, double seconds, const PosePath& path, double rate,
                              const std::atomic<bool>* stop) {
  using clock = std::chrono::steady_clock;
  sim::SimulatedDevice device(port);
  EmulatorReport report;
  std::atomic<bool> sending{true};
  std::vector<clock::time_point> arrivals;
  arrivals.reserve(static_cast<std::size_t>(seconds * rate * 1.5) + 16);
  double max_force = 0.0;
  // The device's receive side: every feedback packet timed on arrival.
  std::thread receiver([&] {
    while (sending.load()) {
      if (const auto feedback = device.receive(5)) {
        arrivals.push_back(clock::now());
        max_force = std::max(max_force, feedback->force.norm());
      }
    }
  });
  const auto start = clock::now();
  const auto period = std::chrono::duration<double>(1.0 / rate);
  for (long long i = 0;; ++i) {
    const auto due = start + std::chrono::duration_cast<clock::duration>(i * period);
    if (std::chrono::duration<double>(due - start).count() >= seconds) break;
    if (stop != nullptr && stop->load()) break;
    std::this_thread::sleep_until(due);
    const double t = std::chrono::duration<double>(clock::now() - start).count();
    sim::DevicePose pose = path(t);
    pose.sequence = static_cast<std::uint32_t>(i + 1);
    pose.time_ns = static_cast<std::uint64_t>(t * 1e9);
    if (device.send(pose)) ++report.poses_sent;
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // the last answers
  sending.store(false);
  receiver.join();

  report.feedback = static_cast<long long>(arrivals.size());
  report.max_force = max_force;
  if (arrivals.size() >= 2) {
    std::vector<double> gaps;
    gaps.reserve(arrivals.size() - 1);
    for (std::size_t i = 1; i < arrivals.size(); ++i)
      gaps.push_back(std::chrono::duration<double>(arrivals[i] - arrivals[i - 1]).count());
    const double span = std::chrono::duration<double>(arrivals.back() - arrivals.front()).count();
    report.feedback_rate = span > 0.0 ? static_cast<double>(gaps.size()) / span : 0.0;
    report.gap_p50 = quantile(gaps, 0.5);
    report.gap_p90 = quantile(gaps, 0.9);
    report.gap_p99 = quantile(gaps, 0.99);
    report.gap_max = gaps.back();
  }
  return report;
}

}  // namespace viscera::testing
