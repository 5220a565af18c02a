#include "core/image/image_volume.h"

#include <cstring>

#include "core/error.h"

namespace viscera::core {

std::size_t scalar_size(ScalarType type) {
  switch (type) {
    case ScalarType::UInt8:
      return 1;
    case ScalarType::Int16:
    case ScalarType::UInt16:
      return 2;
    case ScalarType::Int32:
    case ScalarType::Float32:
      return 4;
    case ScalarType::Float64:
      return 8;
  }
  return 0;
}

std::string scalar_type_name(ScalarType type) {
  switch (type) {
    case ScalarType::UInt8:
      return "uint8";
    case ScalarType::Int16:
      return "int16";
    case ScalarType::UInt16:
      return "uint16";
    case ScalarType::Int32:
      return "int32";
    case ScalarType::Float32:
      return "float32";
    case ScalarType::Float64:
      return "float64";
  }
  return "unknown";
}

ScalarType scalar_type_from_name(const std::string& name) {
  for (const auto type : {ScalarType::UInt8, ScalarType::Int16, ScalarType::UInt16,
                          ScalarType::Int32, ScalarType::Float32, ScalarType::Float64}) {
    if (scalar_type_name(type) == name) return type;
  }
  throw InputError("unknown scalar type \"" + name + "\"");
}

namespace {
template <typename T>
double read_as_double(const std::byte* p) {
  T value;
  std::memcpy(&value, p, sizeof(T));
  return static_cast<double>(value);
}
}  // namespace

double ImageVolume::value(std::size_t linear) const {
  const std::byte* p = voxels.data() + linear * scalar_size(scalar_type);
  switch (scalar_type) {
    case ScalarType::UInt8:
      return read_as_double<std::uint8_t>(p);
    case ScalarType::Int16:
      return read_as_double<std::int16_t>(p);
    case ScalarType::UInt16:
      return read_as_double<std::uint16_t>(p);
    case ScalarType::Int32:
      return read_as_double<std::int32_t>(p);
    case ScalarType::Float32:
      return read_as_double<float>(p);
    case ScalarType::Float64:
      return read_as_double<double>(p);
  }
  return 0.0;
}

void ImageVolume::allocate() {
  voxels.assign(voxel_count() * scalar_size(scalar_type), std::byte{0});
}

std::uint16_t LabelMap::label(std::size_t linear) const {
  std::uint16_t value;
  std::memcpy(&value, image.voxels.data() + 2 * linear, 2);
  return value;
}

void LabelMap::set_label(std::size_t linear, std::uint16_t value) {
  std::memcpy(image.voxels.data() + 2 * linear, &value, 2);
}

}  // namespace viscera::core
