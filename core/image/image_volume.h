#pragma once
/// Image volumes and label maps (DESIGN.md §3). Geometry is kept here, not in VTK: VTK 9.1
/// readers drop the direction matrix (BUILD_NOTES.md).

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/math_types.h"

namespace viscera::core {

/// Voxel scalar types that importers produce.
enum class ScalarType { UInt8, Int16, UInt16, Int32, Float32, Float64 };

/// Bytes per voxel component of a scalar type.
std::size_t scalar_size(ScalarType type);
/// "uint8", "int16", … as stored in files.
std::string scalar_type_name(ScalarType type);
/// Inverse of scalar_type_name; throws InputError for an unknown name.
ScalarType scalar_type_from_name(const std::string& name);

/// A 3D image: dims in voxels, spacing in m, origin in m (centre of voxel 0,0,0), direction
/// cosines as matrix columns, and a dense x-fastest buffer of one component per voxel.
struct ImageVolume {
  std::array<int, 3> dims{0, 0, 0};
  Vec3 spacing = Vec3::Ones();
  Vec3 origin = Vec3::Zero();
  Mat3 direction = Mat3::Identity();
  ScalarType scalar_type = ScalarType::Int16;
  std::vector<std::byte> voxels;

  std::size_t voxel_count() const { return static_cast<std::size_t>(dims[0]) * dims[1] * dims[2]; }
  std::size_t linear_index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * dims[1] + j) * dims[0] + i;
  }
  /// World position in m of the centre of voxel (i, j, k).
  Vec3 index_to_world(const Vec3& ijk) const {
    return origin + direction * spacing.cwiseProduct(ijk);
  }
  /// Voxel value converted to double.
  double value(std::size_t linear) const;
  /// Allocates a zeroed buffer for dims and scalar_type.
  void allocate();

  bool operator==(const ImageVolume&) const = default;
};

/// A label map: an ImageVolume of UInt16 labels (0 = background) with label names.
struct LabelMap {
  ImageVolume image;                 ///< scalar_type UInt16
  std::map<int, std::string> names;  ///< label → tissue name

  std::uint16_t label(std::size_t linear) const;
  void set_label(std::size_t linear, std::uint16_t value);

  bool operator==(const LabelMap&) const = default;
};

}  // namespace viscera::core
