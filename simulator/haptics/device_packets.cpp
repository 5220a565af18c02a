#include "simulator/haptics/device_packets.h"

#include <bit>
#include <cmath>
#include <cstring>

namespace viscera::sim {
namespace {

constexpr std::uint32_t kMagic = 0x44435356;  // "VSCD" read as a little-endian u32
constexpr std::uint16_t kPoseKind = 1, kFeedbackKind = 2;

/// Appends little-endian fields to a fixed buffer.
class Writer {
 public:
  explicit Writer(std::span<std::uint8_t> out) : out_(out) {}
  void u(std::uint64_t value, int bytes) {
    for (int b = 0; b < bytes; ++b)
      out_[at_++] = static_cast<std::uint8_t>(value >> (8 * b));
  }
  void f64(double value) { u(std::bit_cast<std::uint64_t>(value), 8); }
  void f32(float value) { u(std::bit_cast<std::uint32_t>(value), 4); }
  void vec3(const core::Vec3& v) {
    for (int c = 0; c < 3; ++c)
      f64(v[c]);
  }
  void checksum() { u(crc32(out_.first(at_)), 4); }

 private:
  std::span<std::uint8_t> out_;
  std::size_t at_ = 0;
};

/// Reads little-endian fields from a buffer.
class Reader {
 public:
  explicit Reader(std::span<const std::uint8_t> in) : in_(in) {}
  std::uint64_t u(int bytes) {
    std::uint64_t value = 0;
    for (int b = 0; b < bytes; ++b)
      value |= std::uint64_t{in_[at_++]} << (8 * b);
    return value;
  }
  double f64() { return std::bit_cast<double>(u(8)); }
  float f32() { return std::bit_cast<float>(static_cast<std::uint32_t>(u(4))); }
  core::Vec3 vec3() {
    core::Vec3 v;
    for (int c = 0; c < 3; ++c)
      v[c] = f64();
    return v;
  }

 private:
  std::span<const std::uint8_t> in_;
  std::size_t at_ = 0;
};

void header(Writer& w, std::uint16_t kind, std::uint32_t sequence, std::uint64_t time_ns) {
  w.u(kMagic, 4);
  w.u(kDevicePacketVersion, 2);
  w.u(kind, 2);
  w.u(sequence, 4);
  w.u(0, 4);
  w.u(time_ns, 8);
}

/// Checks size, checksum, magic, version and kind; leaves `r` after the header.
bool valid_header(std::span<const std::uint8_t> bytes, std::size_t size, std::uint16_t kind,
                  Reader& r, std::uint32_t& sequence, std::uint64_t& time_ns) {
  if (bytes.size() != size) return false;
  Reader tail(bytes.subspan(size - 4));
  if (tail.u(4) != crc32(bytes.first(size - 4))) return false;
  if (r.u(4) != kMagic || r.u(2) != kDevicePacketVersion || r.u(2) != kind) return false;
  sequence = static_cast<std::uint32_t>(r.u(4));
  r.u(4);
  time_ns = r.u(8);
  return true;
}

}  // namespace

std::uint32_t crc32(std::span<const std::uint8_t> bytes) {
  std::uint32_t crc = 0xFFFFFFFFU;
  for (const std::uint8_t byte : bytes) {
    crc ^= byte;
    for (int bit = 0; bit < 8; ++bit)
      crc = (crc >> 1) ^ (0xEDB88320U & (0U - (crc & 1U)));
  }
  return ~crc;
}

std::array<std::uint8_t, kPosePacketBytes> encode_pose(const DevicePose& p) {
  std::array<std::uint8_t, kPosePacketBytes> out{};
  Writer w(out);
  header(w, kPoseKind, p.sequence, p.time_ns);
  w.vec3(p.position);
  for (const double q : p.orientation)
    w.f64(q);
  w.u(p.buttons, 4);
  w.f32(p.inflow_valve);
  w.f32(p.outflow_valve);
  w.checksum();
  return out;
}

std::array<std::uint8_t, kFeedbackPacketBytes> encode_feedback(const DeviceFeedback& f) {
  std::array<std::uint8_t, kFeedbackPacketBytes> out{};
  Writer w(out);
  header(w, kFeedbackKind, f.sequence, f.time_ns);
  w.vec3(f.force);
  w.vec3(f.torque);
  w.u(f.flags, 4);
  w.checksum();
  return out;
}

std::optional<DevicePose> decode_pose(std::span<const std::uint8_t> bytes) {
  Reader r(bytes);
  DevicePose p;
  if (!valid_header(bytes, kPosePacketBytes, kPoseKind, r, p.sequence, p.time_ns))
    return std::nullopt;
  p.position = r.vec3();
  for (double& q : p.orientation)
    q = r.f64();
  p.buttons = static_cast<std::uint32_t>(r.u(4));
  p.inflow_valve = r.f32();
  p.outflow_valve = r.f32();
  bool finite =
      p.position.allFinite() && std::isfinite(p.inflow_valve) && std::isfinite(p.outflow_valve);
  for (const double q : p.orientation)
    finite = finite && std::isfinite(q);
  if (!finite) return std::nullopt;
  return p;
}

std::optional<DeviceFeedback> decode_feedback(std::span<const std::uint8_t> bytes) {
  Reader r(bytes);
  DeviceFeedback f;
  if (!valid_header(bytes, kFeedbackPacketBytes, kFeedbackKind, r, f.sequence, f.time_ns))
    return std::nullopt;
  f.force = r.vec3();
  f.torque = r.vec3();
  f.flags = static_cast<std::uint32_t>(r.u(4));
  if (!f.force.allFinite() || !f.torque.allFinite()) return std::nullopt;
  return f;
}

}  // namespace viscera::sim
