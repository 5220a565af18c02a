// MINC 1 files' netCDF headers are walked before VTK's MINC reader opens them
// (importers/volume/netcdf_header.h). The volume_minc fuzz finding is refused with the walk's
// sentence, which comes before the netCDF library sees the file (so it never allocated its
// 6.5 GB); every real MINC 1 file of nibabel passes, and a real one cut short is refused.
#include "importers/volume/netcdf_header.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "importers/volume/volume_reader.h"
#include "tests/importers/volume_fixtures.h"

namespace viscera::importers {
namespace {

namespace fs = std::filesystem;

using testing::contains;
using testing::volume_read_error;

TEST(NetcdfHeader, the_fuzz_finding_is_refused_for_its_attribute_before_netcdf_reads_it) {
  const fs::path path = testing::source_dir() /
                        "tests/fuzz/regressions/volume_minc/attribute_count_past_the_file.mnc";
  const std::string message = volume_read_error(path);
  EXPECT_TRUE(contains(message, path.string()) && contains(message, "byte 2676") &&
              contains(message, "declares 1634494823 values of 4 bytes for attribute") &&
              contains(message, "of variable \"image-min\""))
      << message;
}

TEST(NetcdfHeader, every_real_minc1_file_passes) {
  for (const char* name : {"minc1_1_scale.mnc", "minc1-no-att.mnc", "minc1_4d.mnc", "tiny.mnc"}) {
    try {
      detail::check_netcdf_header(testing::nibabel_file(name));
    } catch (const core::InputError& e) {
      ADD_FAILURE() << e.what();
    }
  }
}

TEST(NetcdfHeader, a_real_file_cut_inside_its_image_is_refused_as_truncated) {
  const fs::path path =
      testing::copy_to(testing::nibabel_file("tiny.mnc"), testing::scratch_dir(), "cut.mnc");
  fs::resize_file(path, 5000);  // its 4000 voxels start at byte 3372
  const std::string message = volume_read_error(path);
  EXPECT_TRUE(contains(message, "cut.mnc") &&
              contains(message, "declares 4000 voxels of 1 byte for the image from byte 3372") &&
              contains(message, "truncated"))
      << message;
  fs::resize_file(path, 1000);  // inside the header
  EXPECT_TRUE(contains(volume_read_error(path), "cut short by the end of the file"))
      << volume_read_error(path);
}

}  // namespace
}  // namespace viscera::importers
