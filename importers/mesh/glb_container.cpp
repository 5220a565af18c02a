#include "importers/mesh/glb_container.h"

#include <array>
#include <cstdint>
#include <fstream>
#include <string>

#include "core/error.h"

namespace viscera::importers {
namespace {

std::uint32_t little_endian_u32(const std::array<unsigned char, 4>& bytes) {
  return static_cast<std::uint32_t>(bytes[0]) | static_cast<std::uint32_t>(bytes[1]) << 8 |
         static_cast<std::uint32_t>(bytes[2]) << 16 | static_cast<std::uint32_t>(bytes[3]) << 24;
}

/// Reads four bytes as a little-endian u32; false at the end of the file.
bool read_u32(std::ifstream& in, std::uint32_t& value) {
  std::array<unsigned char, 4> bytes{};
  if (!in.read(reinterpret_cast<char*>(bytes.data()), 4)) return false;
  value = little_endian_u32(bytes);
  return true;
}

}  // namespace

bool is_glb_container(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<char, 4> magic{};
  return in.read(magic.data(), 4) && std::string(magic.data(), 4) == "glTF";
}

void check_glb_container(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  std::ifstream in(path, std::ios::binary);
  std::uint32_t magic = 0, version = 0, length = 0;
  if (error || !read_u32(in, magic) || !read_u32(in, version) || !read_u32(in, length))
    throw core::InputError("the GLB header is cut short (12 bytes expected)", {file, "", ""});
  if (version != 2) {
    throw core::InputError("GLB version " + std::to_string(version) + " is not glTF 2.0's (2)",
                           {file, "", "byte 4"});
  }
  if (length != size) {
    throw core::InputError("the GLB header declares " + std::to_string(length) +
                               " bytes but the file has " + std::to_string(size),
                           {file, "", "byte 8"});
  }
  std::uintmax_t offset = 12;
  while (offset < size) {
    std::uint32_t chunk_length = 0, chunk_type = 0;
    if (size - offset < 8 || !read_u32(in, chunk_length) || !read_u32(in, chunk_type)) {
      throw core::InputError("a GLB chunk header is cut short at the end of the file",
                             {file, "", "byte " + std::to_string(offset)});
    }
    if (chunk_length > size - offset - 8) {
      throw core::InputError("the GLB chunk at byte " + std::to_string(offset) + " declares " +
                                 std::to_string(chunk_length) + " bytes but only " +
                                 std::to_string(size - offset - 8) + " follow",
                             {file, "", "byte " + std::to_string(offset)});
    }
    offset += 8 + chunk_length;
    in.seekg(static_cast<std::streamoff>(offset));
  }
}

}  // namespace viscera::importers
