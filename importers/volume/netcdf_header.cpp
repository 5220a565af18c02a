#include "importers/volume/netcdf_header.h"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"

namespace viscera::importers::detail {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();

/// List tags of the header.
constexpr std::uint64_t kDimensionTag = 0x0A, kVariableTag = 0x0B, kAttributeTag = 0x0C;

/// "1 byte", "4 bytes".
std::string bytes_text(std::uint64_t bytes) {
  return std::to_string(bytes) + (bytes == 1 ? " byte" : " bytes");
}

std::uint64_t saturating_product(std::uint64_t a, std::uint64_t b) {
  return b != 0 && a > kMax / b ? kMax : a * b;
}

/// Bytes of one value of netCDF type `type` (NC_BYTE 1 … NC_UINT64 11); 0 when unknown.
std::uint64_t type_size(std::uint64_t type) {
  static constexpr std::uint64_t kSizes[] = {0, 1, 1, 2, 4, 4, 8, 1, 2, 4, 8, 8};
  return type < std::size(kSizes) ? kSizes[type] : 0;
}

/// Reads the header front to back and refuses, naming the byte, what runs past the file's end.
class HeaderWalk {
 public:
  HeaderWalk(const fs::path& path, std::uint64_t size)
      : file_(path.string()), in_(path, std::ios::binary), size_(size) {}

  std::uint64_t at() const { return at_; }
  std::uint64_t left() const { return size_ - at_; }

  [[noreturn]] void refuse(const std::string& reason, std::uint64_t where) const {
    throw core::InputError("the netCDF header " + reason,
                           {file_, "", "byte " + std::to_string(where)});
  }

  /// A big-endian unsigned number of `bytes` bytes (4 or 8).
  std::uint64_t number(int bytes) {
    unsigned char buffer[8] = {};
    if (left() < static_cast<std::uint64_t>(bytes) ||
        !in_.read(reinterpret_cast<char*>(buffer), bytes))
      refuse("is cut short by the end of the file", at_);
    at_ += static_cast<std::uint64_t>(bytes);
    std::uint64_t value = 0;
    for (int b = 0; b < bytes; ++b)
      value = (value << 8) | buffer[b];
    return value;
  }

  /// Moves past `bytes` bytes that the caller has checked fit in the file.
  void skip(std::uint64_t bytes) {
    at_ += bytes;
    in_.seekg(static_cast<std::streamoff>(at_));
  }

  /// A name: its length, then its bytes padded to a multiple of 4.
  std::string name(int count_bytes) {
    const std::uint64_t start = at_;
    const std::uint64_t length = number(count_bytes);
    const std::uint64_t padded = length > kMax - 3 ? kMax : (length + 3) / 4 * 4;
    if (padded > left()) {
      refuse("has a name of " + std::to_string(length) + " bytes but only " +
                 std::to_string(left()) + " remain",
             start);
    }
    std::string text(static_cast<std::size_t>(std::min<std::uint64_t>(length, 64)), '\0');
    in_.read(text.data(), static_cast<std::streamsize>(text.size()));
    skip(padded);
    for (char& c : text) {
      if (c < 0x20 || c > 0x7e) c = '?';  // a damaged name is quoted in one readable line
    }
    return text;
  }

  /// A list's tag and element count: 0 when absent; refuses a wrong tag or a count whose
  /// elements of at least `least_bytes` each cannot fit in the rest of the file.
  std::uint64_t list(std::uint64_t tag, int count_bytes, std::uint64_t least_bytes,
                     const std::string& what) {
    const std::uint64_t start = at_;
    const std::uint64_t found = number(4);
    const std::uint64_t count = number(count_bytes);
    if (found == 0 && count == 0) return 0;
    if (found != tag) refuse("has no " + what + " list where one belongs", start);
    if (saturating_product(count, least_bytes) > left()) {
      refuse("declares " + std::to_string(count) + " " + what + ", at least " +
                 std::to_string(least_bytes) + " bytes each, but only " + std::to_string(left()) +
                 " bytes remain",
             start);
    }
    return count;
  }

  /// An attribute list; each attribute's values must fit in the rest of the file.
  void attributes(int count_bytes, const std::string& owner) {
    const std::uint64_t count =
        list(kAttributeTag, count_bytes, 2 * static_cast<std::uint64_t>(count_bytes) + 4,
             "attributes of " + owner);
    for (std::uint64_t a = 0; a < count; ++a) {
      const std::string attribute = name(count_bytes);
      const std::uint64_t start = at_;
      const std::uint64_t type = number(4);
      const std::uint64_t values = number(count_bytes);
      if (type_size(type) == 0) {
        refuse("gives attribute \"" + attribute + "\" of " + owner + " an unknown type " +
                   std::to_string(type),
               start);
      }
      const std::uint64_t bytes = saturating_product(values, type_size(type));
      const std::uint64_t padded = bytes > kMax - 3 ? kMax : (bytes + 3) / 4 * 4;
      if (padded > left()) {
        refuse("declares " + std::to_string(values) + " values of " + bytes_text(type_size(type)) +
                   " for attribute \"" + attribute + "\" of " + owner + " but only " +
                   std::to_string(left()) + " bytes remain",
               start);
      }
      skip(padded);
    }
  }

 private:
  std::string file_;
  std::ifstream in_;
  std::uint64_t size_;
  std::uint64_t at_ = 0;
};

}  // namespace

void check_netcdf_header(const fs::path& path) {
  std::error_code error;
  const std::uint64_t size = fs::file_size(path, error);
  if (error) throw core::InputError("cannot read the file", {path.string(), "", ""});
  HeaderWalk walk(path, size);
  const std::uint64_t magic = walk.number(4);
  const std::uint64_t version = magic & 0xff;
  if (magic >> 8 != 0x434446 || (version != 1 && version != 2 && version != 5))
    walk.refuse("has an unknown magic number or version " + std::to_string(version), 0);
  const int count_bytes = version == 5 ? 8 : 4;
  const int offset_bytes = version == 1 ? 4 : 8;
  const auto w = static_cast<std::uint64_t>(count_bytes);
  walk.number(count_bytes);  // records

  std::vector<std::uint64_t> lengths;
  const std::uint64_t dimensions = walk.list(kDimensionTag, count_bytes, 2 * w, "dimensions");
  for (std::uint64_t d = 0; d < dimensions; ++d) {
    walk.name(count_bytes);
    lengths.push_back(walk.number(count_bytes));
  }
  walk.attributes(count_bytes, "the file");

  // Least bytes of a variable: name length, dimension count, an absent attribute list, type,
  // size and data offset.
  const std::uint64_t least_variable = 4 * w + 8 + static_cast<std::uint64_t>(offset_bytes);
  const std::uint64_t variables = walk.list(kVariableTag, count_bytes, least_variable, "variables");
  for (std::uint64_t v = 0; v < variables; ++v) {
    const std::string variable = walk.name(count_bytes);
    const std::uint64_t start = walk.at();
    const std::uint64_t rank = walk.number(count_bytes);
    if (saturating_product(rank, w) > walk.left()) {
      walk.refuse("gives variable \"" + variable + "\" " + std::to_string(rank) +
                      " dimensions, more than the rest of the file can list",
                  start);
    }
    std::uint64_t voxels = 1;
    bool known_extent = true;
    for (std::uint64_t r = 0; r < rank; ++r) {
      const std::uint64_t id = walk.number(count_bytes);
      // The record dimension (length 0) grows with the records; a bad id is netCDF's to refuse.
      known_extent = known_extent && id < lengths.size() && lengths[id] > 0;
      if (known_extent) voxels = saturating_product(voxels, lengths[id]);
    }
    walk.attributes(count_bytes, "variable \"" + variable + "\"");
    const std::uint64_t type_at = walk.at();
    const std::uint64_t type = walk.number(4);
    if (type_size(type) == 0) {
      walk.refuse("gives variable \"" + variable + "\" an unknown type " + std::to_string(type),
                  type_at);
    }
    walk.number(count_bytes);  // vsize: capped for large variables, so the extent is computed
    const std::uint64_t begin = walk.number(offset_bytes);
    const std::uint64_t bytes = saturating_product(voxels, type_size(type));
    if (variable == "image" && known_extent && (begin > size || bytes > size - begin)) {
      walk.refuse("declares " + std::to_string(voxels) + " voxels of " +
                      bytes_text(type_size(type)) + " for the image from byte " +
                      std::to_string(begin) + ", but the file has " + std::to_string(size) +
                      " bytes: it is truncated",
                  start);
    }
  }
}

}  // namespace viscera::importers::detail
