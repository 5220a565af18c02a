#pragma once
// CGAL's liver image for the studio tests that segment a real volume.

#include <array>
#include <filesystem>

#include "core/image/image_volume.h"

namespace viscera::studio_tests {

/// CGAL's liver.inr.gz (438 × 353 × 165 voxels of 0.617 × 0.617 × 1.333 mm; 255 in the liver,
/// 0 outside), extracted from libcgal-demo's data archive into `dir` on first use.
std::filesystem::path cgal_liver(const std::filesystem::path& dir);

/// The voxel of slice near[2] nearest to `near` whose 5 × 5 × 3 neighbourhood is all 255 (deep
/// inside the liver), or {−1, −1, −1}.
std::array<int, 3> deep_inside(const core::ImageVolume& volume, std::array<int, 3> near);

}  // namespace viscera::studio_tests
