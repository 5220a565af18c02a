// Block-average downsampling (core/image/downsample.h) on volumes whose block means are known.
#include "core/image/downsample.h"

#include <gtest/gtest.h>

#include <cstring>

#include "core/error.h"

namespace viscera::core {
namespace {

/// An int16 volume of dims voxels, spacing (1, 2, 3) mm, rotated 90° about z, value i + 10 j +
/// 100 k.
ImageVolume ramp(std::array<int, 3> dims) {
  ImageVolume v;
  v.dims = dims;
  v.spacing = Vec3(0.001, 0.002, 0.003);
  v.origin = Vec3(0.01, -0.02, 0.03);
  v.direction << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  v.scalar_type = ScalarType::Int16;
  v.allocate();
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i) {
        const auto value = static_cast<std::int16_t>(i + 10 * j + 100 * k);
        std::memcpy(v.voxels.data() + 2 * v.linear_index(i, j, k), &value, 2);
      }
  return v;
}

TEST(Downsample, averages_blocks_and_keeps_the_world_frame) {
  const ImageVolume v = ramp({7, 4, 6});
  const ImageVolume d = downsample(v, {2, 2, 3});
  EXPECT_EQ(d.dims, (std::array<int, 3>{3, 2, 2}));  // the seventh column is dropped
  EXPECT_EQ(d.scalar_type, ScalarType::Int16);
  EXPECT_TRUE(d.spacing.isApprox(Vec3(0.002, 0.004, 0.009)));
  EXPECT_TRUE(d.direction == v.direction);
  // The mean of a linear ramp over a block is its value at the block's centre, and the new
  // voxel centre is that block centre in the world: 1.5 ⇒ rounds to 2 (int16).
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) {
        const Vec3 centre(2 * i + 0.5, 2 * j + 0.5, 3 * k + 1.0);
        EXPECT_EQ(d.value(d.linear_index(i, j, k)),
                  std::lround(centre.x() + 10 * centre.y() + 100 * centre.z()));
        EXPECT_TRUE(d.index_to_world(Vec3(i, j, k)).isApprox(v.index_to_world(centre), 1e-12));
      }
}

TEST(Downsample, factor_one_is_the_identity_and_bad_factors_are_refused) {
  const ImageVolume v = ramp({5, 3, 2});
  EXPECT_EQ(downsample(v, {1, 1, 1}), v);
  EXPECT_THROW(downsample(v, {0, 1, 1}), UsageError);
  EXPECT_THROW(downsample(v, {1, 1, 3}), UsageError);
}

TEST(Downsample, float_volumes_keep_fractions) {
  ImageVolume v;
  v.dims = {2, 1, 1};
  v.scalar_type = ScalarType::Float32;
  v.allocate();
  const float values[2] = {1.0f, 2.0f};
  std::memcpy(v.voxels.data(), values, sizeof values);
  const ImageVolume d = downsample(v, {2, 1, 1});
  EXPECT_DOUBLE_EQ(d.value(0), 1.5);
  EXPECT_TRUE(d.origin.isApprox(Vec3(0.5, 0.0, 0.0)));
}

}  // namespace
}  // namespace viscera::core
