#include "core/curves/rotation_minimizing_frames.h"

#include <cmath>

#include "core/error.h"

namespace viscera::core {

Vec3 perpendicular_to(const Vec3& direction, const Vec3& hint) {
  const Vec3 d = direction.normalized();
  const Vec3 projected = hint - hint.dot(d) * d;
  if (projected.norm() > 1e-9 * (1.0 + hint.norm())) return projected.normalized();
  const Vec3 a = d.cwiseAbs();
  const Vec3 axis = a.x() <= a.y() && a.x() <= a.z()
                        ? Vec3::UnitX()
                        : (a.y() <= a.z() ? Vec3::UnitY() : Vec3::UnitZ());
  return (axis - axis.dot(d) * d).normalized();
}

std::vector<CurveFrame> rotation_minimizing_frames(const CubicCurve& curve,
                                                   const std::vector<double>& parameters,
                                                   const Vec3& initial_normal, bool close_loop) {
  if (parameters.empty())
    throw UsageError("rotation-minimising frames need at least one parameter");
  std::vector<CurveFrame> frames(parameters.size());
  CurveFrame& first = frames.front();
  first.origin = curve.point(parameters.front());
  first.tangent = curve.tangent(parameters.front());
  first.normal = perpendicular_to(first.tangent, initial_normal);
  first.binormal = first.tangent.cross(first.normal);

  for (std::size_t i = 0; i + 1 < parameters.size(); ++i) {
    const CurveFrame& f = frames[i];
    CurveFrame& g = frames[i + 1];
    g.origin = curve.point(parameters[i + 1]);
    g.tangent = curve.tangent(parameters[i + 1]);
    // Reflect the frame in the bisector plane of the chord, then in the plane that maps the
    // reflected tangent onto the new tangent (double reflection).
    const Vec3 v1 = g.origin - f.origin;
    const double c1 = v1.dot(v1);
    if (c1 <= 0.0) {
      g.normal = perpendicular_to(g.tangent, f.normal);
      g.binormal = g.tangent.cross(g.normal);
      continue;
    }
    const Vec3 normal_l = f.normal - (2.0 / c1) * v1.dot(f.normal) * v1;
    const Vec3 tangent_l = f.tangent - (2.0 / c1) * v1.dot(f.tangent) * v1;
    const Vec3 v2 = g.tangent - tangent_l;
    const double c2 = v2.dot(v2);
    const Vec3 normal = c2 > 0.0 ? Vec3(normal_l - (2.0 / c2) * v2.dot(normal_l) * v2) : normal_l;
    // Re-orthonormalise against round-off accumulated over many steps.
    g.normal = perpendicular_to(g.tangent, normal);
    g.binormal = g.tangent.cross(g.normal);
  }

  if (close_loop && curve.closed() && frames.size() > 2) {
    // Angle from the transported last normal to the first normal about the common tangent.
    const CurveFrame& last = frames.back();
    const Vec3 target = perpendicular_to(last.tangent, first.normal);
    const double twist =
        std::atan2(last.normal.cross(target).dot(last.tangent), last.normal.dot(target));
    const double span = parameters.back() - parameters.front();
    for (std::size_t i = 1; i < frames.size(); ++i) {
      const double angle = span > 0.0 ? twist * (parameters[i] - parameters.front()) / span : 0.0;
      CurveFrame& f = frames[i];
      const Vec3 n = std::cos(angle) * f.normal + std::sin(angle) * f.binormal;
      f.normal = n.normalized();
      f.binormal = f.tangent.cross(f.normal);
    }
  }
  return frames;
}

}  // namespace viscera::core
