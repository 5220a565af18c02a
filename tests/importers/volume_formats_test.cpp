// NRRD and MetaImage with a separate raw file, written here by hand because no Debian package
// in the set-up ships one: the geometry read must be the header's, converted to metres and LPS.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>

#include "core/error.h"
#include "importers/volume/volume_reader.h"
#include "tests/support/test_paths.h"

namespace viscera::importers {
namespace {

namespace fs = std::filesystem;

/// 4 × 3 × 2 int16 voxels valued by their index, little-endian.
std::string ramp_bytes() {
  std::string bytes;
  for (std::int16_t v = 0; v < 24; ++v)
    bytes.append(reinterpret_cast<const char*>(&v), 2);
  return bytes;
}

TEST(VolumeFormats, nrrd_space_directions_in_ras_become_lps_metres) {
  const fs::path path = testing::scratch_dir() / "oblique.nrrd";
  std::ofstream out(path, std::ios::binary);
  out << "NRRD0004\n# written by the test\ntype: short\ndimension: 3\nspace: "
         "right-anterior-superior\n"
         "sizes: 4 3 2\nspace directions: (0,2,0) (-1.5,0,0) (0,0,3)\nkinds: domain domain domain\n"
         "endian: little\nencoding: raw\nspace origin: (10,-20,30)\n\n"
      << ramp_bytes();
  out.close();
  const auto loaded = read_volume(path);
  const auto& v = loaded.volume;
  EXPECT_EQ(loaded.format, "NRRD");
  EXPECT_EQ(v.dims, (std::array<int, 3>{4, 3, 2}));
  EXPECT_TRUE(v.spacing.isApprox(core::Vec3(0.002, 0.0015, 0.003), 1e-12));
  // RAS (10, −20, 30) mm is LPS (−10, 20, 30) mm; +i steps 2 mm anterior = −y in LPS.
  EXPECT_TRUE(v.origin.isApprox(core::Vec3(-0.010, 0.020, 0.030), 1e-12));
  EXPECT_TRUE(v.direction.col(0).isApprox(core::Vec3(0, -1, 0)));
  EXPECT_TRUE(v.direction.col(1).isApprox(core::Vec3(1, 0, 0)));
  EXPECT_TRUE(v.direction.col(2).isApprox(core::Vec3(0, 0, 1)));
  EXPECT_EQ(v.value(v.linear_index(3, 2, 1)), 23.0);
}

TEST(VolumeFormats, a_nrrd_byte_skip_that_is_not_a_number_is_a_typed_error_naming_the_field) {
  // std::stol's std::invalid_argument used to escape the reader untyped.
  const fs::path dir = testing::scratch_dir();
  for (const char* skip : {"lots", "12abc", "99999999999999999999999"}) {
    std::ofstream(dir / "skip.nrrd", std::ios::binary)
        << "NRRD0004\ntype: short\ndimension: 3\nsizes: 4 3 2\nendian: little\nencoding: raw\n"
        << "byte skip: " << skip << "\n\n"
        << ramp_bytes();
    try {
      read_volume(dir / "skip.nrrd");
      ADD_FAILURE() << "no error for byte skip " << skip;
    } catch (const core::InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("skip.nrrd"), std::string::npos) << message;
      EXPECT_NE(message.find(std::string("byte skip: ") + skip), std::string::npos) << message;
    }
  }
}

TEST(VolumeFormats, nrrd_gzip_data_reads_and_a_truncated_nrrd_is_refused) {
  const fs::path dir = testing::scratch_dir();
  std::ofstream(dir / "ramp.raw", std::ios::binary) << ramp_bytes();
  ASSERT_EQ(std::system(
                ("gzip -c " + (dir / "ramp.raw").string() + " > " + (dir / "ramp.raw.gz").string())
                    .c_str()),
            0);
  std::ofstream(dir / "ramp.nhdr")
      << "NRRD0004\ntype: int16\ndimension: 3\nsizes: 4 3 2\nspacings: 1 2 3\n"
         "endian: little\nencoding: gzip\ndata file: ramp.raw.gz\n";
  const auto loaded = read_volume(dir / "ramp.nhdr");
  EXPECT_EQ(loaded.volume.value(23), 23.0);
  EXPECT_TRUE(loaded.volume.spacing.isApprox(core::Vec3(0.001, 0.002, 0.003), 1e-12));
  std::ofstream(dir / "cut.nrrd", std::ios::binary)
      << "NRRD0004\ntype: short\ndimension: 3\nsizes: 4 3 2\nendian: little\nencoding: raw\n\n"
      << ramp_bytes().substr(0, 30);
  try {
    read_volume(dir / "cut.nrrd");
    ADD_FAILURE() << "no error";
  } catch (const core::InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("cut.nrrd"), std::string::npos) << message;
    EXPECT_NE(message.find("header asks for 48 bytes of voxels, the file holds 30"),
              std::string::npos)
        << message;
  }
}

TEST(VolumeFormats, metaimage_with_a_raw_file_keeps_its_transform_matrix) {
  const fs::path dir = testing::scratch_dir();
  std::ofstream(dir / "ramp.raw", std::ios::binary) << ramp_bytes();
  std::ofstream(dir / "ramp.mhd")
      << "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n"
         "TransformMatrix = 0 1 0 -1 0 0 0 0 1\nOffset = 5 6 7\nElementSpacing = 0.5 0.25 2\n"
         "DimSize = 4 3 2\nElementType = MET_SHORT\nElementDataFile = ramp.raw\n";
  const auto loaded = read_volume(dir / "ramp.mhd");
  const auto& v = loaded.volume;
  EXPECT_EQ(loaded.files.size(), 2u);
  EXPECT_TRUE(v.spacing.isApprox(core::Vec3(0.0005, 0.00025, 0.002), 1e-12));
  EXPECT_TRUE(v.origin.isApprox(core::Vec3(0.005, 0.006, 0.007), 1e-12));
  // ITK writes the direction of axis c as the c-th triple: +i is +y, +j is −x.
  EXPECT_TRUE(v.direction.col(0).isApprox(core::Vec3(0, 1, 0)));
  EXPECT_TRUE(v.direction.col(1).isApprox(core::Vec3(-1, 0, 0)));
  EXPECT_EQ(v.value(v.linear_index(1, 1, 1)), 17.0);
  // Its raw file gone: refused naming the header and the missing file.
  fs::remove(dir / "ramp.raw");
  try {
    read_volume(dir / "ramp.mhd");
    ADD_FAILURE() << "no error";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ramp.raw named by the header is missing"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("ramp.mhd"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace viscera::importers
