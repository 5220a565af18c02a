#include "importers/volume/nifti_header.h"

#include <zlib.h>

#include <array>
#include <cstdint>
#include <string>

#include "core/error.h"

namespace viscera::importers::detail {
namespace {

/// The datatype codes of nifti1.h that vtkNIFTIImageReader reads, with their bits per voxel.
struct Datatype {
  int code;
  int bits;
  const char* name;
};
constexpr std::array<Datatype, 14> kReadable{{{2, 8, "UINT8"},
                                              {4, 16, "INT16"},
                                              {8, 32, "INT32"},
                                              {16, 32, "FLOAT32"},
                                              {32, 64, "COMPLEX64"},
                                              {64, 64, "FLOAT64"},
                                              {128, 24, "RGB24"},
                                              {256, 8, "INT8"},
                                              {512, 16, "UINT16"},
                                              {768, 32, "UINT32"},
                                              {1024, 64, "INT64"},
                                              {1280, 64, "UINT64"},
                                              {1792, 128, "COMPLEX128"},
                                              {2304, 32, "RGBA32"}}};

std::uint32_t read_u32(const unsigned char* p, bool big_endian) {
  return big_endian ? (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) |
                          (std::uint32_t{p[2]} << 8) | p[3]
                    : (std::uint32_t{p[3]} << 24) | (std::uint32_t{p[2]} << 16) |
                          (std::uint32_t{p[1]} << 8) | p[0];
}

int read_i16(const unsigned char* p, bool big_endian) {
  const auto value =
      static_cast<std::uint16_t>(big_endian ? (p[0] << 8) | p[1] : (p[1] << 8) | p[0]);
  return static_cast<std::int16_t>(value);
}

}  // namespace

void check_nifti_header(const std::filesystem::path& path) {
  const std::string file = path.string();
  // gzread reads an uncompressed file as it is, so one path serves .nii, .hdr and .nii.gz.
  gzFile in = gzopen(file.c_str(), "rb");
  if (in == nullptr) throw core::InputError("cannot open the file", {file, "", ""});
  std::array<unsigned char, 540> header{};
  const int got = gzread(in, header.data(), static_cast<unsigned>(header.size()));
  gzclose(in);
  if (got < 348) {
    throw core::InputError("the header is cut short: the file holds " +
                               std::to_string(got < 0 ? 0 : got) +
                               " bytes, a NIfTI-1 or Analyze header has 348",
                           {file, "", "sizeof_hdr"});
  }
  int size = 0;
  bool big_endian = false;
  for (const bool order : {false, true}) {
    const std::uint32_t value = read_u32(header.data(), order);
    if (value == 348 || value == 540) {
      size = static_cast<int>(value);
      big_endian = order;
      break;
    }
  }
  if (size == 0) {
    throw core::InputError(
        "not a NIfTI or Analyze header: its size field (bytes 0-3) is " +
            std::to_string(read_u32(header.data(), false)) + " little-endian and " +
            std::to_string(read_u32(header.data(), true)) + " big-endian, neither 348 nor 540",
        {file, "", "sizeof_hdr"});
  }
  if (size == 540 && got < 540) {
    throw core::InputError("the NIfTI-2 header is cut short: the file holds " +
                               std::to_string(got) + " bytes of its 540",
                           {file, "", "sizeof_hdr"});
  }
  const std::size_t at = size == 348 ? 70 : 12;
  const int datatype = read_i16(header.data() + at, big_endian);
  const int bitpix = read_i16(header.data() + at + 2, big_endian);
  for (const Datatype& type : kReadable) {
    if (type.code != datatype) continue;
    if (type.bits != bitpix) {
      throw core::InputError("the header's bits per voxel (bitpix " + std::to_string(bitpix) +
                                 ") differ from its datatype " + type.name + "'s " +
                                 std::to_string(type.bits),
                             {file, "", "bitpix"});
    }
    return;
  }
  throw core::InputError("the header's datatype " + std::to_string(datatype) +
                             " is not a voxel type VTK's NIfTI reader reads",
                         {file, "", "datatype"});
}

}  // namespace viscera::importers::detail
