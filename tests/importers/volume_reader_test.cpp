// read_volume() on every real image file that Debian's pydicom, nibabel and CGAL packages ship,
// compared with what their headers state (volume_headers.py reads them through pydicom and
// nibabel), and on every kind of bad volume input: one InputError naming the file and reason.
#include "importers/volume/volume_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>

#include "core/error.h"
#include "tests/importers/volume_fixtures.h"
#include "tests/support/test_paths.h"

namespace viscera::importers {
namespace {

namespace fs = std::filesystem;

/// Real files GDCM 3.0 or VTK 9.1 cannot read, and the reason read_volume() must give.
const std::map<std::string, std::string> kUnreadable = {
    {"JPEG2000-embedded-sequence-delimiter.dcm", "cannot decode the pixel data"},
    {"SC_ybr_full_422_uncompressed.dcm",
     "chroma-subsampled colour (YBR_FULL_422) is not supported"},
    {"rtdose_1frame.dcm", "without Number of Frames"},
    {"rtdose_expb_1frame.dcm", "without Number of Frames"},
    {"rtdose_rle_1frame.dcm", "without Number of Frames"},
    // VTK's MINC reader needs the step attribute that nibabel defaults to 1.
    {"minc1-no-att.mnc", "The attribute zspace:step was not found"},
};

using testing::contains;
using testing::volume_read_error;

std::vector<core::Vec3> corners_mm(const core::ImageVolume& v) {
  std::vector<core::Vec3> corners;
  for (int k : {0, v.dims[2] - 1})
    for (int j : {0, v.dims[1] - 1})
      for (int i : {0, v.dims[0] - 1})
        corners.push_back(1000.0 * v.index_to_world(core::Vec3(i, j, k)));
  return corners;
}

void expect_geometry(const nlohmann::json& entry, const LoadedVolume& loaded) {
  const core::ImageVolume& v = loaded.volume;
  const std::string name = entry["path"];
  const auto& dims = entry["dims"];
  const auto& spacing = entry["spacing_mm"];
  if (entry["format"] == "MINC") {
    // nibabel keeps MINC's file order of axes; compare (size, spacing) pairs as sets.
    std::vector<std::pair<int, long>> expected, actual;
    for (int a = 0; a < 3; ++a) {
      expected.emplace_back(dims[a].get<int>(), std::lround(1000 * spacing[a].get<double>()));
      actual.emplace_back(v.dims[a], std::lround(1e6 * v.spacing[a]));
    }
    std::sort(expected.begin(), expected.end());
    std::sort(actual.begin(), actual.end());
    EXPECT_EQ(actual, expected) << name;
  } else {
    for (int a = 0; a < 3; ++a) {
      EXPECT_EQ(v.dims[a], dims[a].get<int>()) << name << " axis " << a;
      if (!spacing.is_null() && !spacing[a].is_null()) {
        EXPECT_NEAR(1000 * v.spacing[a], spacing[a].get<double>(), 1e-5 * spacing[a].get<double>())
            << name << " axis " << a;
      }
    }
  }
  if (entry["format"] == "DICOM" && spacing.is_null()) {
    EXPECT_EQ(v.spacing.head<2>(), core::Vec2(0.001, 0.001)) << name;
    EXPECT_TRUE(std::any_of(loaded.notes.begin(), loaded.notes.end(), [](const auto& n) {
      return contains(n, "no Pixel Spacing");
    })) << name;
  }
  if (entry.contains("corners_lps_mm")) {
    // The world positions of the corner voxels, whatever order the reader keeps the axes in.
    const auto ours = corners_mm(v);
    for (const auto& c : entry["corners_lps_mm"]) {
      const core::Vec3 expected(c[0].get<double>(), c[1].get<double>(), c[2].get<double>());
      const bool found = std::any_of(ours.begin(), ours.end(), [&](const core::Vec3& p) {
        return (p - expected).norm() < 1e-3;
      });
      EXPECT_TRUE(found) << name << ": no corner voxel at " << expected.transpose() << " mm";
    }
  }
  if (entry.contains("value_range")) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < v.voxel_count(); ++i) {
      lo = std::min(lo, v.value(i));
      hi = std::max(hi, v.value(i));
    }
    EXPECT_NEAR(lo, entry["value_range"][0].get<double>(), 1e-6) << name;
    EXPECT_NEAR(hi, entry["value_range"][1].get<double>(), 1e-6) << name;
  }
  if (entry.contains("other_series")) {
    EXPECT_EQ(static_cast<int>(loaded.other_series.size()), entry["other_series"].get<int>())
        << name;
  }
}

TEST(VolumeReader, every_real_file_reads_with_the_geometry_its_header_states) {
  const auto headers = testing::real_volume_headers(testing::scratch_dir());
  ASSERT_TRUE(headers.is_array());
  std::map<std::string, int> read, refused;
  for (const auto& entry : headers) {
    const fs::path path = entry["path"].get<std::string>();
    const std::string format = entry["format"];
    const auto unreadable = kUnreadable.find(path.filename().string());
    if (entry.contains("error") || unreadable != kUnreadable.end()) {
      const std::string reason =
          unreadable != kUnreadable.end() ? unreadable->second : entry["error"].get<std::string>();
      const std::string message = volume_read_error(path);
      EXPECT_TRUE(contains(message, path.string()) && contains(message, reason))
          << path << " should be refused for \"" << reason << "\", got: " << message;
      ++refused[format];
      continue;
    }
    try {
      expect_geometry(entry, read_volume(path));
      ++read[format];
    } catch (const core::Error& e) {
      ADD_FAILURE() << path << ": " << e.what();
    }
  }
  // Every package's files were there and looked at.
  EXPECT_GE(read["DICOM"], 45);
  EXPECT_GE(read["NIfTI"], 6);
  EXPECT_GE(read["MINC"], 3);
  EXPECT_GE(read["INRIMAGE"], 6);
  EXPECT_GE(refused["DICOM"], 7);     // truncated, no pixel data, codecs GDCM lacks
  EXPECT_GE(refused["MINC"], 5);      // MINC 2
  EXPECT_GE(refused["NIfTI"], 4);     // headers without their .img, NaN voxels
  EXPECT_GE(refused["INRIMAGE"], 1);  // small-scalar.inr is cut short
}

TEST(VolumeReader, every_encoding_of_the_same_mr_slice_gives_the_same_voxels) {
  // Little/big endian, explicit/implicit VR, RLE, JPEG-LS and JPEG 2000 lossless of one image.
  const auto reference = read_volume(testing::pydicom_file("MR_small.dcm")).volume;
  for (const char* name :
       {"MR_small_bigendian.dcm", "MR_small_expb.dcm", "MR_small_implicit.dcm", "MR_small_RLE.dcm",
        "MR_small_jpeg_ls_lossless.dcm", "MR_small_jp2klossless.dcm", "MR_small_padded.dcm"}) {
    const auto volume = read_volume(testing::pydicom_file(name)).volume;
    EXPECT_EQ(volume.voxels, reference.voxels) << name;
    EXPECT_EQ(volume.origin, reference.origin) << name;
    EXPECT_EQ(volume.scalar_type, reference.scalar_type) << name;
  }
}

TEST(VolumeReader, ct_is_read_in_hounsfield_units_at_its_patient_position) {
  const auto loaded = read_volume(testing::pydicom_file("CT_small.dcm"));
  EXPECT_EQ(loaded.volume.scalar_type, core::ScalarType::Int16);  // slope 1, intercept −1024
  // Image Position (Patient) −158.135803, −179.035797, −75.699997 mm.
  EXPECT_TRUE(
      loaded.volume.origin.isApprox(core::Vec3(-0.158135803, -0.179035797, -0.075699997), 1e-9));
}

TEST(VolumeReader, a_dicom_folder_reads_its_largest_series_ordered_along_the_normal) {
  const auto loaded = read_volume(testing::pydicom_file("dicomdirtests/98892001"));
  ASSERT_EQ(loaded.other_series.size(), 1u);
  EXPECT_EQ(loaded.other_series[0].files, 2);
  EXPECT_EQ(loaded.other_series[0].description, "Scout");
  ASSERT_EQ(loaded.files.size(), 5u);
  // Slices at z = 8.7625 … −1.2375 mm: the first voxel plane is the lowest one.
  EXPECT_NEAR(loaded.volume.origin.z(), -0.0012375, 1e-9);
  EXPECT_NEAR(loaded.volume.index_to_world(core::Vec3(0, 0, 4)).z(), 0.0087625, 1e-9);
}

TEST(VolumeReader, dicom_folders_whose_slices_do_not_stack_are_refused_naming_why) {
  const std::string radial = volume_read_error(testing::pydicom_file("dicomdirtests/98892003"));
  EXPECT_TRUE(contains(radial, "98892003") && contains(radial, "slices are not parallel"))
      << radial;
  const std::string gap = volume_read_error(testing::pydicom_file("dicomdirtests/77654033"));
  EXPECT_TRUE(contains(gap, "77654033") && contains(gap, "not evenly spaced") &&
              contains(gap, "202.5 mm"))
      << gap;
  const fs::path empty = testing::scratch_dir();
  std::ofstream(empty / "notes.txt") << "no images here\n";
  EXPECT_TRUE(contains(volume_read_error(empty), "folder holds no DICOM image"))
      << volume_read_error(empty);
}

TEST(VolumeReader, a_truncated_dicom_is_refused_naming_the_file) {
  const fs::path path = testing::pydicom_file("MR_truncated.dcm");
  const std::string message = volume_read_error(path);
  EXPECT_TRUE(contains(message, path.string()) && contains(message, "pixel data is truncated") &&
              contains(message, "8192 bytes"))
      << message;
}

TEST(VolumeReader, a_truncated_nifti_is_refused_naming_the_file) {
  const fs::path dir = testing::scratch_dir();
  const fs::path path = testing::copy_to(testing::nibabel_file("anatomical.nii"), dir, "cut.nii");
  fs::resize_file(path, fs::file_size(path) / 2);
  const std::string message = volume_read_error(path);
  EXPECT_TRUE(contains(message, path.string()) && contains(message, "file is truncated"))
      << message;
}

TEST(VolumeReader, a_nifti_header_claiming_huge_dims_is_refused_before_allocation) {
  const fs::path dir = testing::scratch_dir();
  const fs::path path = testing::copy_to(testing::nibabel_file("anatomical.nii"), dir, "huge.nii");
  {
    // NIfTI-1 dim[1..3] are int16 at bytes 42, 44, 46, in the byte order of sizeof_hdr (348).
    std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
    unsigned char size[4];
    file.read(reinterpret_cast<char*>(size), 4);
    const bool big_endian = size[3] == 348 % 256 && size[2] == 348 / 256;
    const char huge[2] = {big_endian ? '\x75' : '\x30', big_endian ? '\x30' : '\x75'};  // 30000
    for (const int offset : {42, 44, 46}) {
      file.seekp(offset);
      file.write(huge, 2);
    }
  }
  const std::string message = volume_read_error(path);
  EXPECT_TRUE(contains(message, path.string()) &&
              contains(message, "header claims 30000×30000×30000 voxels") &&
              contains(message, "memory limit of 4096 MiB"))
      << message;
  // A real file over a small stated limit is refused the same way.
  VolumeReadOptions small;
  small.max_bytes = 1024;
  const std::string limited = volume_read_error(testing::nibabel_file("anatomical.nii"), small);
  EXPECT_TRUE(contains(limited, "header claims 33×41×25 voxels")) << limited;
}

TEST(VolumeReader, nan_voxels_are_refused_naming_the_voxel) {
  const fs::path path = testing::scratch_dir() / "nan.mha";
  std::ofstream out(path, std::ios::binary);
  out << "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n"
         "ElementSpacing = 1 1 1\nDimSize = 2 2 1\nElementType = MET_FLOAT\nElementDataFile = "
         "LOCAL\n";
  const float values[4] = {1.0f, 2.0f, std::numeric_limits<float>::quiet_NaN(), 4.0f};
  out.write(reinterpret_cast<const char*>(values), sizeof values);
  out.close();
  const std::string message = volume_read_error(path);
  EXPECT_TRUE(contains(message, path.string()) &&
              contains(message, "voxel (0, 1, 0) is NaN or infinite"))
      << message;
}

TEST(VolumeReader, missing_empty_and_unknown_files_are_refused) {
  const fs::path dir = testing::scratch_dir();
  EXPECT_TRUE(contains(volume_read_error(dir / "absent.nii"), "no such file or folder"));
  std::ofstream(dir / "empty.nii").close();
  EXPECT_TRUE(contains(volume_read_error(dir / "empty.nii"), "file is empty"));
  std::ofstream(dir / "photo.png") << "not a volume";
  const std::string unknown = volume_read_error(dir / "photo.png");
  EXPECT_TRUE(contains(unknown, "photo.png") && contains(unknown, "not an image volume format"))
      << unknown;
  std::ofstream(dir / "garbage.nii") << std::string(400, 'x');
  const std::string garbage = volume_read_error(dir / "garbage.nii");
  EXPECT_TRUE(contains(garbage, "garbage.nii")) << garbage;
}

}  // namespace
}  // namespace viscera::importers
