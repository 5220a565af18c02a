// The NIfTI header is checked before VTK's reader sees it (importers/volume/nifti_header.h): the
// volume_nifti fuzz findings whose datatype VTK did not refuse the same way twice are refused
// with one sentence every time, and every real NIfTI-1, NIfTI-2 and Analyze header of nibabel's
// test data passes, compressed or not.
#include "importers/volume/nifti_header.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <set>

#include "core/error.h"
#include "tests/importers/volume_fixtures.h"

namespace viscera::importers::detail {
namespace {

namespace fs = std::filesystem;

using testing::contains;
using testing::volume_read_error;

std::string header_problem(const fs::path& path) {
  try {
    check_nifti_header(path);
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "no error";
}

/// nibabel's anatomical.nii with `bytes` written at `offset`, in the scratch folder.
fs::path patched_anatomical(const std::string& name, std::size_t offset, const std::string& bytes) {
  std::ifstream in(testing::nibabel_file("anatomical.nii"), std::ios::binary);
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  data.replace(offset, bytes.size(), bytes);
  const fs::path file = testing::scratch_dir() / name;
  std::ofstream(file, std::ios::binary) << data;
  return file;
}

TEST(NiftiHeader, every_real_header_of_nibabel_passes) {
  for (const char* name : {"anatomical.nii", "functional.nii", "standard.nii.gz",
                           "example4d.nii.gz", "example_nifti2.nii.gz", "analyze.hdr", "nifti1.hdr",
                           "nifti2.hdr", "reoriented_anat_moved.nii", "resampled_anat_moved.nii"}) {
    EXPECT_EQ(header_problem(testing::nibabel_file(name)), "no error") << name;
  }
}

TEST(NiftiHeader, the_fuzz_findings_are_refused_the_same_way_every_time) {
  const fs::path finding =
      testing::source_dir() /
      "tests/fuzz/regressions/volume_nifti/gigabytes_for_a_384_byte_header.nii";
  std::set<std::string> messages;
  for (int run = 0; run < 5; ++run)
    messages.insert(volume_read_error(finding));
  ASSERT_EQ(messages.size(), 1u) << *messages.begin() << " / " << *messages.rbegin();
  EXPECT_TRUE(contains(*messages.begin(), finding.string()) &&
              contains(*messages.begin(), "datatype") &&
              contains(*messages.begin(), "is not a voxel type VTK's NIfTI reader reads"))
      << *messages.begin();
  const fs::path stop20 =
      testing::source_dir() /
      "tests/fuzz/regressions/volume_nifti/big_endian_datatype_vtk_reads_at_random.nii";
  EXPECT_TRUE(contains(header_problem(stop20), "datatype: the header's datatype -32767"))
      << header_problem(stop20);
}

TEST(NiftiHeader, a_cut_header_a_wrong_size_field_and_a_bitpix_that_contradicts_the_type) {
  const fs::path tiny = testing::scratch_dir() / "tiny.nii";
  std::ofstream(tiny, std::ios::binary) << std::string(100, '\0');
  EXPECT_TRUE(contains(header_problem(tiny),
                       "the file holds 100 bytes, a NIfTI-1 or Analyze "
                       "header has 348"))
      << header_problem(tiny);
  const fs::path size = patched_anatomical("size.nii", 0, std::string("\x2c\x01\0\0", 4));
  EXPECT_TRUE(contains(header_problem(size), "size field (bytes 0-3) is 300 little-endian"))
      << header_problem(size);
  // anatomical.nii is big-endian INT16 (datatype 4, bitpix 16): claim 8 bits per voxel.
  const fs::path bits = patched_anatomical("bits.nii", 72, std::string("\0\x08", 2));
  EXPECT_TRUE(contains(header_problem(bits),
                       "bitpix: the header's bits per voxel (bitpix 8) "
                       "differ from its datatype INT16's 16"))
      << header_problem(bits);
  EXPECT_TRUE(contains(volume_read_error(bits), "bitpix 8")) << volume_read_error(bits);
}

}  // namespace
}  // namespace viscera::importers::detail
