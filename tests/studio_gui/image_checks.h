#pragma once
/// Pixel statistics and a synthetic CT phantom for the studio's window tests.

#include <QImage>
#include <array>
#include <filesystem>

namespace viscera::studio_tests {

/// Share of pixels of `image` whose red exceeds blue by 30: organ tissue, not background.
double tissue_share(const QImage& image);
/// Standard deviation of the grey levels of `image` (0 for a blank image).
double grey_deviation(const QImage& image);
/// Writes a CT-like int16 .vti of 2 mm voxels centred on the origin (origin at
/// -(dims-1) mm): a sphere of `radius` m whose values fall from +1000 HU at the centre to
/// +500 HU at its rim, in -1000 HU air.
void write_phantom(const std::filesystem::path& path, std::array<int, 3> dims, double radius);

}  // namespace viscera::studio_tests
