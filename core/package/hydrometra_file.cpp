#include "core/package/hydrometra_file.h"

#include <bit>
#include <cstdint>
#include <cstring>

#include "core/error.h"

namespace viscera::core {
namespace {

constexpr char kMagic[] = "VHYDRO01";
constexpr std::size_t kMagicSize = 8;
constexpr std::size_t kHeaderSize = kMagicSize + 4 + 4 + 8;

void put_u32(std::string& out, std::uint32_t value) {
  for (int i = 0; i < 4; ++i)
    out.push_back(static_cast<char>((value >> (8 * i)) & 0xffU));
}
void put_f64(std::string& out, double value) {
  const auto bits = std::bit_cast<std::uint64_t>(value);
  for (int i = 0; i < 8; ++i)
    out.push_back(static_cast<char>((bits >> (8 * i)) & 0xffU));
}
std::uint64_t get_le(const std::string& in, std::size_t at, int bytes) {
  std::uint64_t value = 0;
  for (int i = 0; i < bytes; ++i)
    value |=
        static_cast<std::uint64_t>(static_cast<unsigned char>(in[at + static_cast<std::size_t>(i)]))
        << (8 * i);
  return value;
}
double get_f64(const std::string& in, std::size_t at) {
  return std::bit_cast<double>(get_le(in, at, 8));
}

}  // namespace

std::string hydrometra_file_of(const std::string& object_id) {
  return "objects/" + object_id + "/hydrometra.bin";
}

std::string hydrometra_bytes(const HydrometraStates& states) {
  std::string out;
  out.reserve(kHeaderSize + 8 * states.pressures.size() + 24 * states.displacements.size());
  out.append(kMagic, kMagicSize);
  put_u32(out, static_cast<std::uint32_t>(states.pressures.size()));
  put_u32(out, static_cast<std::uint32_t>(states.node_count));
  put_f64(out, states.residual);
  for (const double p : states.pressures)
    put_f64(out, p);
  for (const Vec3& u : states.displacements)
    for (int c = 0; c < 3; ++c)
      put_f64(out, u[c]);
  return out;
}

HydrometraStates read_hydrometra_bytes(const std::string& bytes, const std::string& file) {
  const auto fail = [&](const std::string& message) { throw InputError(message, {file, "", ""}); };
  if (bytes.size() < kHeaderSize || std::memcmp(bytes.data(), kMagic, kMagicSize) != 0)
    fail("not a hydrometra states file (magic VHYDRO01 missing)");
  const std::uint64_t states = get_le(bytes, kMagicSize, 4);
  const std::uint64_t nodes = get_le(bytes, kMagicSize + 4, 4);
  // Sizes in 64 bits: at most 2³² × 2³² × 24 would overflow, so check before multiplying.
  if (nodes > (1ULL << 28) || states > (1ULL << 20))
    fail("hydrometra header sizes are implausible");
  const std::uint64_t expected = kHeaderSize + 8 * states + 24 * states * nodes;
  if (bytes.size() != expected)
    fail("hydrometra file has " + std::to_string(bytes.size()) + " bytes, its header says " +
         std::to_string(expected));
  HydrometraStates result;
  result.node_count = static_cast<int>(nodes);
  result.residual = get_f64(bytes, kMagicSize + 8);
  std::size_t at = kHeaderSize;
  result.pressures.resize(states);
  for (double& p : result.pressures) {
    p = get_f64(bytes, at);
    at += 8;
  }
  result.displacements.resize(states * nodes);
  for (Vec3& u : result.displacements) {
    for (int c = 0; c < 3; ++c) {
      u[c] = get_f64(bytes, at);
      at += 8;
    }
  }
  check_hydrometra_states(result, file);
  return result;
}

}  // namespace viscera::core
