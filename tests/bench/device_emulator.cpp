#include "tests/bench/device_emulator.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <pthread.h>
#include <sched.h>
#include <sys/socket.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <optional>
#include <span>
#include <thread>
#include <vector>

#include "core/error.h"

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

namespace {

/// The emulator's UDP socket on loopback, with kernel receive time stamps (SO_TIMESTAMPNS): the
/// arrival of each feedback packet is timed by the kernel, not by when the receiving thread got
/// to run, so the gaps measure the simulator's sending alone.
class TimedSocket {
 public:
  TimedSocket() {
    fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    if (fd_ < 0) throw core::Error("the device emulator cannot open a UDP socket");
    sockaddr_in local{};
    local.sin_family = AF_INET;
    local.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    const int on = 1;
    timeval wait{0, 5000};  // receive() returns every 5 ms so the receiver can stop
    if (::bind(fd_, reinterpret_cast<const sockaddr*>(&local), sizeof local) != 0 ||
        ::setsockopt(fd_, SOL_SOCKET, SO_TIMESTAMPNS, &on, sizeof on) != 0 ||
        ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &wait, sizeof wait) != 0) {
      ::close(fd_);
      throw core::Error("the device emulator cannot bind its UDP socket");
    }
  }
  ~TimedSocket() { ::close(fd_); }
  TimedSocket(const TimedSocket&) = delete;
  TimedSocket& operator=(const TimedSocket&) = delete;

  bool send_to(std::uint16_t port, std::span<const std::uint8_t> bytes) const {
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    to.sin_port = htons(port);
    return ::sendto(fd_, bytes.data(), bytes.size(), 0, reinterpret_cast<const sockaddr*>(&to),
                    sizeof to) == static_cast<ssize_t>(bytes.size());
  }

  /// One datagram into `buffer` with its kernel arrival time in s; nullopt after 5 ms idle.
  std::optional<std::size_t> receive(std::vector<std::uint8_t>& buffer, double& arrival) const {
    buffer.resize(2048);
    iovec data{buffer.data(), buffer.size()};
    alignas(cmsghdr) char control[CMSG_SPACE(sizeof(timespec))];
    msghdr message{};
    message.msg_iov = &data;
    message.msg_iovlen = 1;
    message.msg_control = control;
    message.msg_controllen = sizeof control;
    const ssize_t got = ::recvmsg(fd_, &message, 0);
    if (got < 0) return std::nullopt;
    arrival = -1.0;
    for (cmsghdr* c = CMSG_FIRSTHDR(&message); c != nullptr; c = CMSG_NXTHDR(&message, c)) {
      if (c->cmsg_level == SOL_SOCKET && c->cmsg_type == SCM_TIMESTAMPNS) {
        timespec stamp{};
        std::memcpy(&stamp, CMSG_DATA(c), sizeof stamp);
        arrival = static_cast<double>(stamp.tv_sec) + 1e-9 * static_cast<double>(stamp.tv_nsec);
      }
    }
    return static_cast<std::size_t>(got);
  }

 private:
  int fd_ = -1;
};

/// A device's servo loop runs at a real-time priority: ask for it (best effort), so the
/// emulator's own sending is not what the measurement sees.
void raise_priority() {
  sched_param priority{};
  priority.sched_priority = 20;
  pthread_setschedparam(pthread_self(), SCHED_FIFO, &priority);
}

}  // namespace

EmulatorReport emulate_device(std::uint16_t port, double seconds, const PosePath& path, double rate,
                              const std::atomic<bool>* stop) {
  using clock = std::chrono::steady_clock;
  const TimedSocket device;
  EmulatorReport report;
  std::atomic<bool> sending{true};
  std::vector<double> arrivals;
  arrivals.reserve(static_cast<std::size_t>(seconds * rate * 1.5) + 16);
  double max_force = 0.0;
  // The device's receive side: every feedback packet with its kernel arrival time.
  std::thread receiver([&] {
    raise_priority();
    std::vector<std::uint8_t> buffer;
    double arrival = 0.0;
    while (sending.load()) {
      const auto size = device.receive(buffer, arrival);
      if (!size) continue;
      const auto feedback =
          sim::decode_feedback(std::span<const std::uint8_t>(buffer.data(), *size));
      if (!feedback || arrival < 0.0) continue;
      arrivals.push_back(arrival);
      max_force = std::max(max_force, feedback->force.norm());
    }
  });
  std::thread sender([&] {
    raise_priority();
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
      if (device.send_to(port, sim::encode_pose(pose))) ++report.poses_sent;
    }
  });
  sender.join();
  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // the last answers
  sending.store(false);
  receiver.join();

  report.feedback = static_cast<long long>(arrivals.size());
  report.max_force = max_force;
  if (arrivals.size() >= 2) {
    std::vector<double> gaps;
    gaps.reserve(arrivals.size() - 1);
    for (std::size_t i = 1; i < arrivals.size(); ++i)
      gaps.push_back(arrivals[i] - arrivals[i - 1]);
    const double span = arrivals.back() - arrivals.front();
    report.feedback_rate = span > 0.0 ? static_cast<double>(gaps.size()) / span : 0.0;
    report.gap_p50 = quantile(gaps, 0.5);
    report.gap_p90 = quantile(gaps, 0.9);
    report.gap_p99 = quantile(gaps, 0.99);
    report.gap_max = gaps.back();
  }
  return report;
}

}  // namespace viscera::testing
