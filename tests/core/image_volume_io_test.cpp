#include "core/image/image_volume_io.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstring>
#include <fstream>

#include "core/error.h"
#include "tests/support/test_paths.h"

namespace viscera::core {
namespace {

ImageVolume oblique_volume() {
  ImageVolume v;
  v.dims = {5, 4, 3};
  v.spacing = Vec3(0.0005, 0.0007, 0.002);
  v.origin = Vec3(-0.1, 0.05, 0.2);
  v.direction = Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  v.scalar_type = ScalarType::Int16;
  v.allocate();
  for (std::size_t i = 0; i < v.voxel_count(); ++i) {
    const auto value = static_cast<std::int16_t>(static_cast<int>(i) * 37 - 1000);
    std::memcpy(v.voxels.data() + 2 * i, &value, 2);
  }
  return v;
}

TEST(ImageVolumeIo, vti_round_trip_keeps_geometry_and_voxels) {
  const auto dir = viscera::testing::scratch_dir();
  const ImageVolume original = oblique_volume();
  write_volume_vti(original, dir / "v.vti");
  const ImageVolume back = read_volume_vti(dir / "v.vti");
  EXPECT_EQ(back.dims, original.dims);
  EXPECT_EQ(back.spacing, original.spacing);
  EXPECT_EQ(back.origin, original.origin);
  EXPECT_TRUE(back.direction.isApprox(original.direction, 1e-15));
  EXPECT_EQ(back.voxels, original.voxels);
  EXPECT_DOUBLE_EQ(back.value(3), -1000.0 + 3 * 37);
  // The world position of a voxel follows origin + direction · (spacing ∘ index).
  EXPECT_TRUE(back.index_to_world(Vec3(1, 0, 0))
                  .isApprox(original.origin + original.direction.col(0) * 0.0005));
}

TEST(ImageVolumeIo, label_map_round_trip_keeps_names) {
  const auto dir = viscera::testing::scratch_dir();
  LabelMap labels;
  labels.image.dims = {3, 3, 3};
  labels.image.scalar_type = ScalarType::UInt16;
  labels.image.allocate();
  labels.set_label(13, 2);
  labels.names = {{1, "myometrium"}, {2, "myoma"}};
  write_label_map_vti(labels, dir / "labels.vti");
  const LabelMap back = read_label_map_vti(dir / "labels.vti");
  EXPECT_EQ(back, labels);
  EXPECT_EQ(back.label(13), 2);
}

TEST(ImageVolumeIo, refuses_garbage_and_wrong_label_types_naming_the_file) {
  const auto dir = viscera::testing::scratch_dir();
  std::ofstream(dir / "junk.vti") << "<VTKFile type=\"ImageData\"";
  try {
    read_volume_vti(dir / "junk.vti");
    FAIL() << "garbage accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("junk.vti"), std::string::npos);
  }
  write_volume_vti(oblique_volume(), dir / "ct.vti");
  EXPECT_THROW(read_label_map_vti(dir / "ct.vti"), InputError);
}

}  // namespace
}  // namespace viscera::core
