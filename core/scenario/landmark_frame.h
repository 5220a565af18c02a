#pragma once
/// A landmark's frame, the one scripts place the instrument in (sim::resolve_script_landmarks)
/// and templates check room in: n the landmark's unit normal (ẑ when it has none), u = n × ẑ
/// made unit — across, horizontal whenever n is not vertical (n × x̂ when it is) — and
/// v = n × u. For a pathology's base landmark on the uterine wall, v points along the wall
/// towards the cervix and n out of the wall.

#include "core/scenario/scenario_parts.h"

namespace viscera::core {

struct LandmarkFrame {
  Vec3 u = Vec3::UnitX(), v = Vec3::UnitY(), n = Vec3::UnitZ();
  /// The offset a u + b v + c n for `abc` = (a, b, c).
  Vec3 offset(const Vec3& abc) const { return abc.x() * u + abc.y() * v + abc.z() * n; }
};

/// The frame of a landmark with normal `normal` (any length; zero: ẑ).
inline LandmarkFrame landmark_frame(const Vec3& normal) {
  LandmarkFrame f;
  f.n = normal.norm() > 0.0 ? Vec3(normal.normalized()) : Vec3(Vec3::UnitZ());
  f.u = f.n.cross(Vec3::UnitZ());
  if (f.u.norm() < 1e-6) f.u = f.n.cross(Vec3::UnitX());
  f.u.normalize();
  f.v = f.n.cross(f.u);
  return f;
}

}  // namespace viscera::core
