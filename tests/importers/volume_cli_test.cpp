// `viscera volume info|convert` and `viscera segment` run as a user runs them, on real files:
// exit codes of DESIGN.md §9, one line naming the file on bad input, nothing written then.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/image/image_volume_io.h"
#include "core/segmentation/label_operations.h"
#include "importers/volume/volume_reader.h"
#include "tests/importers/volume_fixtures.h"
#include "tests/support/command_runner.h"
#include "tests/support/test_paths.h"

namespace viscera {
namespace {

namespace fs = std::filesystem;
using testing::run_program;
using testing::shell_quote;

bool one_line_naming(const std::string& err, const std::string& file, const std::string& reason) {
  return std::count(err.begin(), err.end(), '\n') == 1 && err.find(file) != std::string::npos &&
         err.find(reason) != std::string::npos;
}

TEST(VolumeCommand, volume_and_segment_have_help) {
  const fs::path dir = testing::scratch_dir();
  for (const char* command : {"volume info", "volume convert", "segment"}) {
    const auto result = run_program("viscera", std::string(command) + " --help", dir);
    EXPECT_EQ(result.exit_code, 0) << command;
    EXPECT_NE(result.out.find("Usage"), std::string::npos) << command;
  }
}

TEST(VolumeCommand, info_prints_the_geometry_of_a_real_ct_and_a_dicom_folder) {
  const fs::path dir = testing::scratch_dir();
  const auto ct = run_program(
      "viscera",
      "volume info --json " + shell_quote(testing::pydicom_file("CT_small.dcm").string()), dir);
  ASSERT_EQ(ct.exit_code, 0) << ct.err;
  const auto json = nlohmann::json::parse(ct.out);
  EXPECT_EQ(json["format"], "DICOM");
  EXPECT_EQ(json["dims"], nlohmann::json({128, 128, 1}));
  EXPECT_NEAR(json["spacing_mm"][0].get<double>(), 0.661468, 1e-9);   // Pixel Spacing of the header
  EXPECT_NEAR(json["origin_mm"][2].get<double>(), -75.699997, 1e-6);  // Image Position (Patient)
  EXPECT_EQ(json["scalar_type"], "int16");
  const auto folder = run_program(
      "viscera",
      "volume info " + shell_quote(testing::pydicom_file("dicomdirtests/98892001").string()), dir);
  ASSERT_EQ(folder.exit_code, 0) << folder.err;
  EXPECT_NE(folder.out.find("16 × 16 × 5"), std::string::npos) << folder.out;
  EXPECT_NE(folder.out.find("other series"), std::string::npos) << folder.out;
  EXPECT_NE(folder.out.find("\"Scout\" (2 files)"), std::string::npos) << folder.out;
}

TEST(VolumeCommand, a_file_the_codecs_cannot_decode_gives_one_line_and_exit_3) {
  // The JPEG 2000 codec under GDCM complains on stderr itself; the user sees our line only.
  const fs::path dir = testing::scratch_dir();
  const fs::path file = testing::pydicom_file("JPEG2000-embedded-sequence-delimiter.dcm");
  const auto result = run_program("viscera", "volume info " + shell_quote(file.string()), dir);
  EXPECT_EQ(result.exit_code, 3);
  EXPECT_TRUE(one_line_naming(result.err, file.string(), "cannot decode the pixel data"))
      << result.err;
  // The memory limit of the command line: CGAL's 438 × 353 × 165 liver (24.3 MiB) over 16 MiB.
  const fs::path liver = testing::cgal_images(dir) / "liver.inr.gz";
  const auto limited =
      run_program("viscera", "volume info --max-memory 16 " + shell_quote(liver.string()), dir);
  EXPECT_EQ(limited.exit_code, 3);
  EXPECT_TRUE(one_line_naming(
      limited.err, liver.string(),
      "header claims 438×353×165 voxels (24 MiB), more than the memory limit of 16 MiB"))
      << limited.err;
}

TEST(VolumeCommand, convert_keeps_geometry_and_voxels_in_every_format) {
  const fs::path dir = testing::scratch_dir();
  const fs::path input = testing::nibabel_file("example4d.nii.gz");  // oblique, 2 × 2 × 2.2 mm
  const auto original = importers::read_volume(input).volume;
  for (const char* name : {"out.nii.gz", "out.nii", "out.mha", "out.vti"}) {
    const fs::path output = dir / name;
    const auto result = run_program(
        "viscera",
        "volume convert " + shell_quote(input.string()) + " -o " + shell_quote(output.string()),
        dir);
    ASSERT_EQ(result.exit_code, 0) << name << ": " << result.err;
    const auto back = importers::read_volume(output).volume;
    EXPECT_EQ(back.dims, original.dims) << name;
    EXPECT_EQ(back.voxels, original.voxels) << name;
    EXPECT_TRUE(back.spacing.isApprox(original.spacing, 1e-6)) << name;
    EXPECT_LT((back.origin - original.origin).norm(), 1e-7) << name;
    EXPECT_TRUE(back.direction.isApprox(original.direction, 1e-5)) << name;
  }
  // Bad input: exit 3, one line naming the file, nothing written.
  const fs::path truncated = testing::pydicom_file("MR_truncated.dcm");
  const auto bad = run_program("viscera",
                               "volume convert " + shell_quote(truncated.string()) + " -o " +
                                   shell_quote((dir / "bad.vti").string()),
                               dir);
  EXPECT_EQ(bad.exit_code, 3);
  EXPECT_TRUE(one_line_naming(bad.err, truncated.string(), "pixel data is truncated")) << bad.err;
  EXPECT_FALSE(fs::exists(dir / "bad.vti"));
}

TEST(VolumeCommand, segment_turns_a_real_volume_into_a_label_map_the_mesher_reads) {
  const fs::path dir = testing::scratch_dir();
  const fs::path liver = testing::cgal_images(dir) / "liver.inr.gz";  // 438 × 353 × 165, 0 / 255
  const fs::path output = dir / "liver_labels.vti";
  const auto result = run_program(
      "viscera",
      "segment " + shell_quote(liver.string()) + " -o " + shell_quote(output.string()) +
          " --threshold 128:255=2 --open 1 --largest --relabel 2=1 --name 1=liver --json",
      dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  const core::LabelMap labels = core::read_label_map_vti(output);
  EXPECT_EQ(labels.image.dims, (std::array<int, 3>{438, 353, 165}));
  EXPECT_NEAR(labels.image.spacing.x(), 0.000617188, 1e-12);  // VX of the INRIMAGE header
  EXPECT_EQ(labels.names.at(1), "liver");
  const auto counts = core::label_counts(labels);
  ASSERT_EQ(counts.size(), 1u);
  EXPECT_EQ(json["labels"][0]["voxels"].get<std::size_t>(), counts.at(1));
  // Without opening and largest component the label holds every voxel above the threshold.
  const auto raw =
      run_program("viscera",
                  "segment " + shell_quote(liver.string()) + " -o " +
                      shell_quote((dir / "raw.vti").string()) + " --threshold 128:255 --json",
                  dir);
  ASSERT_EQ(raw.exit_code, 0) << raw.err;
  const auto raw_count = nlohmann::json::parse(raw.out)["labels"][0]["voxels"].get<std::size_t>();
  const auto volume = importers::read_volume(liver).volume;
  std::size_t above = 0;
  for (std::size_t v = 0; v < volume.voxel_count(); ++v)
    above += volume.value(v) >= 128 ? 1 : 0;
  EXPECT_EQ(raw_count, above);
  EXPECT_LT(counts.at(1), raw_count);
}

TEST(VolumeCommand, segment_region_grows_from_a_point_in_millimetres) {
  const fs::path dir = testing::scratch_dir();
  const fs::path liver = testing::cgal_images(dir) / "liver.inr.gz";
  const fs::path output = dir / "grown.vti";
  // A point inside the liver (voxel 219, 176, 82 at 0.617188 × 0.617188 × 1.33333 mm).
  const auto volume = importers::read_volume(liver).volume;
  const core::Vec3 seed = 1000.0 * volume.index_to_world(core::Vec3(219, 176, 82));
  ASSERT_GT(volume.value(volume.linear_index(219, 176, 82)), 128.0);
  const std::string point =
      std::to_string(seed.x()) + "," + std::to_string(seed.y()) + "," + std::to_string(seed.z());
  const auto result =
      run_program("viscera",
                  "segment " + shell_quote(liver.string()) + " -o " + shell_quote(output.string()) +
                      " --grow " + point + ":0=5 --json",
                  dir);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto labels = core::read_label_map_vti(output);
  const auto counts = core::label_counts(labels);
  ASSERT_EQ(counts.count(5), 1u);
  // Region growing with tolerance 0 gives the connected piece of the seed's value.
  EXPECT_EQ(core::label_counts(core::keep_largest_component(labels)).at(5), counts.at(5));
}

TEST(VolumeCommand, segment_refuses_bad_input_and_options_writing_nothing) {
  const fs::path dir = testing::scratch_dir();
  const fs::path ct = testing::pydicom_file("CT_small.dcm");
  const fs::path output = dir / "labels.vti";
  // A window no voxel falls in: the label map would be empty.
  const auto empty = run_program("viscera",
                                 "segment " + shell_quote(ct.string()) + " -o " +
                                     shell_quote(output.string()) + " --threshold 5000:6000",
                                 dir);
  EXPECT_EQ(empty.exit_code, 3);
  EXPECT_TRUE(one_line_naming(empty.err, ct.string(), "the segmentation labels no voxel"))
      << empty.err;
  EXPECT_FALSE(fs::exists(output));
  // Unreadable input.
  const fs::path minc2 = testing::nibabel_file("minc2_1_scale.mnc");
  const auto unreadable = run_program("viscera",
                                      "segment " + shell_quote(minc2.string()) + " -o " +
                                          shell_quote(output.string()) + " --threshold 0:1",
                                      dir);
  EXPECT_EQ(unreadable.exit_code, 3);
  EXPECT_TRUE(one_line_naming(unreadable.err, minc2.string(), "MINC 2 (HDF5)")) << unreadable.err;
  // Malformed options are usage errors.
  for (const char* options : {"--threshold 5", "--threshold 10:1", "--grow 1,2", "--open 1",
                              "--threshold 0:1 --merge 1,2"}) {
    const auto usage = run_program("viscera",
                                   "segment " + shell_quote(ct.string()) + " -o " +
                                       shell_quote(output.string()) + " " + options,
                                   dir);
    EXPECT_EQ(usage.exit_code, 2) << options << ": " << usage.err;
  }
  const auto outside = run_program("viscera",
                                   "segment " + shell_quote(ct.string()) + " -o " +
                                       shell_quote(output.string()) + " --grow 0,0,0",
                                   dir);
  EXPECT_EQ(outside.exit_code, 2);
  EXPECT_NE(outside.err.find("lies outside the volume"), std::string::npos) << outside.err;
  EXPECT_FALSE(fs::exists(output));
}

}  // namespace
}  // namespace viscera
