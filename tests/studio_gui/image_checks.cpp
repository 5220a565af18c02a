#include "tests/studio_gui/image_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/image/image_volume.h"
#include "core/image/image_volume_io.h"

namespace fs = std::filesystem;
using namespace viscera;

namespace viscera::studio_tests {

/// Share of pixels of `image` whose red exceeds blue by 30: organ tissue, not background.
double tissue_share(const QImage& image) {
  const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
  std::int64_t tissue = 0;
  for (int y = 0; y < rgb.height(); ++y) {
    for (int x = 0; x < rgb.width(); ++x) {
      const QRgb p = rgb.pixel(x, y);
      if (qRed(p) > qBlue(p) + 30) ++tissue;
    }
  }
  return static_cast<double>(tissue) / (static_cast<double>(rgb.width()) * rgb.height());
}

/// Standard deviation of the grey levels of `image`.
double grey_deviation(const QImage& image) {
  const QImage grey = image.convertToFormat(QImage::Format_Grayscale8);
  double sum = 0.0, sum2 = 0.0;
  for (int y = 0; y < grey.height(); ++y) {
    const uchar* row = grey.constScanLine(y);
    for (int x = 0; x < grey.width(); ++x) {
      sum += row[x];
      sum2 += static_cast<double>(row[x]) * row[x];
    }
  }
  const double n = static_cast<double>(grey.width()) * grey.height();
  return std::sqrt(std::max(0.0, sum2 / n - (sum / n) * (sum / n)));
}

/// A CT-like int16 volume of 2 mm voxels centred on the origin: a sphere of `radius` m whose
/// values fall from +1000 HU at the centre to +500 HU at its rim, in -1000 HU air.
void write_phantom(const fs::path& path, std::array<int, 3> dims, double radius) {
  core::ImageVolume volume;
  volume.dims = dims;
  volume.spacing = core::Vec3::Constant(0.002);
  volume.origin = -0.001 * core::Vec3(dims[0] - 1, dims[1] - 1, dims[2] - 1);
  volume.scalar_type = core::ScalarType::Int16;
  volume.allocate();
  auto* voxels = reinterpret_cast<std::int16_t*>(volume.voxels.data());
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i) {
        const double r = volume.index_to_world(core::Vec3(i, j, k)).norm();
        voxels[volume.linear_index(i, j, k)] =
            static_cast<std::int16_t>(r < radius ? 1000.0 - 500.0 * r / radius : -1000.0);
      }
  core::write_volume_vti(volume, path);
}

}  // namespace viscera::studio_tests
