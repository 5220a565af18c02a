#pragma once
/// Vector types shared by every module. Positions are in metres (SI inside, DESIGN.md §3).

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products wherever vectors are used
#include <array>
#include <limits>

namespace viscera::core {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Triangle = std::array<int, 3>;     ///< vertex indices, counter-clockwise seen from outside
using Tetrahedron = std::array<int, 4>;  ///< node indices with positive signed volume

/// Axis-aligned box; empty() until a point is added.
struct BoundingBox {
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 max = Vec3::Constant(-std::numeric_limits<double>::infinity());

  void add(const Vec3& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  bool empty() const { return (min.array() > max.array()).any(); }
  Vec3 size() const { return empty() ? Vec3::Zero() : Vec3(max - min); }
  Vec3 center() const { return 0.5 * (min + max); }
};

}  // namespace viscera::core
