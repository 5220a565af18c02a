// DICOM files are checked before GDCM reads them (importers/volume/dicom_element_lengths.h):
// every element length against the bytes after it, and uncompressed pixel data against the image
// the header declares. The volume_dicom_file fuzz finding is refused with the walk's sentence,
// which comes before any GDCM read (so GDCM never allocated its 3 GB), and every real DICOM file
// of pydicom and nibabel walks clean but the three that are cut short.
#include "importers/volume/dicom_element_lengths.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>

#include "core/error.h"
#include "importers/volume/volume_reader.h"
#include "tests/importers/volume_fixtures.h"

namespace viscera::importers {
namespace {

namespace fs = std::filesystem;

using testing::contains;
using testing::volume_read_error;

/// A regression file of the volume_dicom_file fuzz target.
fs::path regression(const std::string& name) {
  return testing::source_dir() / "tests/fuzz/regressions/volume_dicom_file" / name;
}

fs::path finding() {
  return regression("element_length_past_the_file.dcm");
}

/// The walk's sentence for `file` (it must have one), after checking that reading the file fails
/// with an error naming it and `element`.
std::string walk_refusal(const fs::path& file, const std::string& element) {
  const std::string message = volume_read_error(file);
  EXPECT_TRUE(contains(message, file.string()) && contains(message, element)) << message;
  return detail::dicom_length_problem(file).value_or("(the walk found nothing)");
}

TEST(DicomElementLengths, the_fuzz_finding_is_refused_for_its_element_before_gdcm_reads_it) {
  const std::string message = volume_read_error(finding());
  EXPECT_TRUE(contains(message, finding().string()) &&
              contains(message, "damaged DICOM data element (EB00,CD00) at byte 9692") &&
              contains(message, "declares 3019946752 bytes, the file holds 33 after it"))
      << message;
}

TEST(DicomElementLengths, native_pixels_of_undefined_length_are_refused_before_gdcm_reads_on) {
  // The fourth fuzz pass's finding: a big-endian slice whose Pixel Data lost its VR and length
  // to 0xFF bytes; GDCM read the pixels on as elements and asked for 4 GB in the parse guard.
  const std::string problem =
      walk_refusal(regression("native_pixels_of_undefined_length.dcm"), "(7FE0,0010)");
  EXPECT_TRUE(contains(problem,
                       "pixel data is damaged: (7FE0,0010) at byte 1504 has an "
                       "undefined length"))
      << problem;
}

TEST(DicomElementLengths, a_meta_element_without_a_vr_is_read_as_gdcm_reads_it_and_refused) {
  // Stop 18's finding: 253 bytes whose first meta element (0002,5800) has the VR bytes CD 0C.
  // GDCM reads it as implicit VR, takes the next four bytes as its length (0xE0000CCD) and
  // zero-filled 3.76 GB in the parse guard's child before it asserted.
  EXPECT_EQ(
      walk_refusal(regression("meta_element_without_vr_declaring_gigabytes.dcm"), "(0002,5800)"),
      "damaged DICOM data element (0002,5800) at byte 132 declares 3758099661 bytes, the "
      "file holds 113 after it");
}

TEST(DicomElementLengths, a_folder_is_read_without_the_file_and_lists_it_with_the_reason) {
  const fs::path folder = testing::scratch_dir() / "series";
  fs::create_directories(folder);
  fs::copy_file(testing::pydicom_file("CT_small.dcm"), folder / "good.dcm");
  fs::copy_file(finding(), folder / "stray.dcm");
  const auto loaded = read_volume(folder);
  ASSERT_EQ(loaded.files.size(), 1u);
  EXPECT_EQ(loaded.files.front().filename(), "good.dcm");
  ASSERT_EQ(loaded.skipped_files.size(), 1u);
  EXPECT_EQ(loaded.skipped_files.front().file.filename(), "stray.dcm");
  EXPECT_TRUE(contains(loaded.skipped_files.front().reason, "(EB00,CD00)"))
      << loaded.skipped_files.front().reason;
}

TEST(DicomElementLengths, every_real_file_walks_clean_but_those_cut_short) {
  const std::map<std::string, std::string> cut_short = {
      {"MR_truncated.dcm", "pixel data is truncated: (7FE0,0010) at byte 1488 declares 8192"},
      {"rtplan_truncated.dcm", "(300A,00B0) at byte 1410 declares 976 bytes"},
      {"DICOMDIR-nooffset", "the sequence item at byte 10860 declares 248 bytes"},
  };
  int walked = 0;
  for (const char* folder : {"/usr/lib/python3/dist-packages/pydicom/data/test_files",
                             "/usr/lib/python3/dist-packages/nibabel"}) {
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
      const fs::path& file = entry.path();
      const bool dicom = file.extension() == ".dcm" || contains(file.string(), "dicomdirtests");
      if (!entry.is_regular_file() || !dicom) continue;
      ++walked;
      const auto problem = detail::dicom_length_problem(file);
      const auto expected = cut_short.find(file.filename().string());
      if (expected == cut_short.end()) {
        EXPECT_FALSE(problem) << file << ": " << problem.value_or("");
      } else {
        EXPECT_TRUE(problem && contains(*problem, expected->second))
            << file << ": " << problem.value_or("no problem found");
      }
    }
  }
  EXPECT_GE(walked, 150);
}

TEST(DicomElementLengths, uncompressed_pixels_the_file_cannot_hold_are_refused_before_allocation) {
  // pydicom's MR slice with Rows (0028,0010) raised from 64 to 65535: 8.4 MB in a 9.8 KB file.
  std::string bytes = testing::file_bytes(testing::pydicom_file("MR_small.dcm"));
  ASSERT_EQ(bytes.substr(1370, 2), std::string("\x40\x00", 2));
  bytes.replace(1370, 2, "\xff\xff");
  const fs::path path = testing::scratch_dir() / "rows.dcm";
  std::ofstream(path, std::ios::binary) << bytes;
  const std::string message = volume_read_error(path);
  EXPECT_TRUE(contains(message, "rows.dcm") && contains(message, "pixel data is truncated") &&
              contains(message, "64×65535 pixels") && contains(message, "(8388480 bytes)"))
      << message;
}

}  // namespace
}  // namespace viscera::importers
