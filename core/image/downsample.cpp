#include "core/image/downsample.h"

#include <cmath>
#include <cstring>
#include <string>

#include "core/error.h"

namespace viscera::core {
namespace {

template <typename T>
void store(std::byte* p, double value) {
  T typed;
  if constexpr (std::is_floating_point_v<T>) {
    typed = static_cast<T>(value);
  } else {
    typed = static_cast<T>(std::lround(value));
  }
  std::memcpy(p, &typed, sizeof(T));
}

void store_value(ImageVolume& volume, std::size_t linear, double value) {
  std::byte* p = volume.voxels.data() + linear * scalar_size(volume.scalar_type);
  switch (volume.scalar_type) {
    case ScalarType::UInt8:
      return store<std::uint8_t>(p, value);
    case ScalarType::Int16:
      return store<std::int16_t>(p, value);
    case ScalarType::UInt16:
      return store<std::uint16_t>(p, value);
    case ScalarType::Int32:
      return store<std::int32_t>(p, value);
    case ScalarType::Float32:
      return store<float>(p, value);
    case ScalarType::Float64:
      return store<double>(p, value);
  }
}

}  // namespace

ImageVolume downsample(const ImageVolume& volume, const std::array<int, 3>& factors) {
  for (int a = 0; a < 3; ++a) {
    if (factors[a] < 1 || factors[a] > volume.dims[a]) {
      throw UsageError("downsampling factor " + std::to_string(factors[a]) + " along axis " +
                       std::to_string(a) + " must lie in 1…" + std::to_string(volume.dims[a]));
    }
  }
  ImageVolume out;
  out.scalar_type = volume.scalar_type;
  out.direction = volume.direction;
  for (int a = 0; a < 3; ++a) {
    out.dims[a] = volume.dims[a] / factors[a];
    out.spacing[a] = volume.spacing[a] * factors[a];
  }
  out.origin = volume.index_to_world(
      Vec3(0.5 * (factors[0] - 1), 0.5 * (factors[1] - 1), 0.5 * (factors[2] - 1)));
  out.allocate();
  const double block = static_cast<double>(factors[0]) * factors[1] * factors[2];
  for (int k = 0; k < out.dims[2]; ++k) {
    for (int j = 0; j < out.dims[1]; ++j) {
      for (int i = 0; i < out.dims[0]; ++i) {
        double sum = 0.0;
        for (int c = 0; c < factors[2]; ++c)
          for (int b = 0; b < factors[1]; ++b)
            for (int a = 0; a < factors[0]; ++a)
              sum += volume.value(
                  volume.linear_index(i * factors[0] + a, j * factors[1] + b, k * factors[2] + c));
        store_value(out, out.linear_index(i, j, k), sum / block);
      }
    }
  }
  return out;
}

}  // namespace viscera::core
