// DICOM files that make GDCM abort (Debian builds it with assertions on) are refused or skipped
// with their name, and the process reading them lives on (issue 21: a flipped byte in the file
// meta header of a CT slice killed `viscera volume info` with SIGABRT).
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "core/crash_guard.h"
#include "core/error.h"
#include "importers/volume/volume_reader.h"
#include "tests/importers/volume_fixtures.h"
#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"

namespace viscera {
namespace {

namespace fs = std::filesystem;

/// pydicom's CT slice with the VR of (0002,0003) Media Storage SOP Instance UID changed from
/// "UI" to "UK" (byte 197): GDCM 3.0 asserts in ReadExplicitDataElement on it.
fs::path damaged_ct(const fs::path& where) {
  std::ifstream in(testing::pydicom_file("CT_small.dcm"), std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(bytes.substr(196, 2), "UI");
  bytes[197] = 'K';
  const fs::path file = where / "damaged.dcm";
  std::ofstream(file, std::ios::binary) << bytes;
  return file;
}

/// A regression file of the volume_dicom_file fuzz target.
fs::path dicom_regression(const std::string& name) {
  return testing::source_dir() / "tests/fuzz/regressions/volume_dicom_file" / name;
}

TEST(DamagedDicom, a_file_that_aborts_gdcm_is_refused_naming_it_and_the_reader_survives) {
  const fs::path file = damaged_ct(testing::scratch_dir());
  try {
    importers::read_volume(file);
    FAIL() << "the damaged file was read";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("damaged.dcm"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("damaged DICOM data element"), std::string::npos)
        << e.what();
  }
}

TEST(DamagedDicom, a_file_whose_spacing_aborts_gdcms_image_reader_is_refused_naming_it) {
  // Stop 20's volume_dicom_file finding: GDCM parses the file's elements, then asserts in
  // ImageHelper::GetSpacingValue while its image reader interprets them.
  const fs::path file = dicom_regression("spacing_that_gdcm_image_helper_asserts_on.dcm");
  const std::string message = testing::volume_read_error(file);
  EXPECT_TRUE(testing::contains(message, file.string()) &&
              testing::contains(message, "GDCM aborts or hangs"))
      << message;
}

TEST(DamagedDicom, a_file_whose_recovery_parse_asks_gigabytes_is_refused_within_the_bound) {
  if (!core::guard_limits_memory()) GTEST_SKIP() << "sanitizer build: guards do not limit memory";
  // Stop 20's second volume_dicom_file finding (20 KB): GDCM's first parse fails, its 16-bit
  // length recovery reads an item tag's bytes as a length and zero-filled 4.2 GB for 6 s in the
  // guard's child; the parse's bound (the file's size and 2 GiB) refuses it at once.
  const std::string message =
      testing::volume_read_error(dicom_regression("recovery_parse_zero_fills_gigabytes.dcm"));
  EXPECT_TRUE(testing::contains(message, "GDCM aborts or hangs")) << message;
  rusage children{};
  ::getrusage(RUSAGE_CHILDREN, &children);  // the largest child this process waited for
  EXPECT_LT(children.ru_maxrss, 2L << 20) << "KB in a guard's child";
}

TEST(DamagedDicom, a_folder_is_read_without_the_files_that_abort_gdcm_and_lists_them) {
  const fs::path dir = testing::scratch_dir();
  const fs::path folder = dir / "series";
  fs::create_directories(folder);
  fs::copy_file(testing::pydicom_file("CT_small.dcm"), folder / "good.dcm");
  const fs::path damaged = damaged_ct(folder);
  const auto loaded = importers::read_volume(folder);
  ASSERT_EQ(loaded.files.size(), 1u);
  EXPECT_EQ(loaded.files.front().filename(), "good.dcm");
  ASSERT_EQ(loaded.skipped_files.size(), 1u);
  EXPECT_EQ(loaded.skipped_files.front().file.filename(), damaged.filename());
  EXPECT_EQ(loaded.volume.dims, (std::array<int, 3>{128, 128, 1}));
}

TEST(DamagedDicom, volume_info_exits_3_with_one_line_naming_the_file) {
  const fs::path dir = testing::scratch_dir();
  const fs::path file = damaged_ct(dir);
  const auto result =
      testing::run_program("viscera", "volume info " + testing::shell_quote(file.string()), dir);
  EXPECT_EQ(result.exit_code, 3) << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  EXPECT_NE(result.err.find(file.string()), std::string::npos) << result.err;
  EXPECT_EQ(result.err.find("Assertion"), std::string::npos) << result.err;
}

TEST(DamagedDicom, volume_info_of_a_folder_lists_the_skipped_file) {
  const fs::path dir = testing::scratch_dir();
  const fs::path folder = dir / "series";
  fs::create_directories(folder);
  fs::copy_file(testing::pydicom_file("CT_small.dcm"), folder / "good.dcm");
  damaged_ct(folder);
  const auto result = testing::run_program(
      "viscera", "volume info --json " + testing::shell_quote(folder.string()), dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  ASSERT_EQ(json["skipped_files"].size(), 1u);
  EXPECT_NE(json["skipped_files"][0]["file"].get<std::string>().find("damaged.dcm"),
            std::string::npos);
}

}  // namespace
}  // namespace viscera
