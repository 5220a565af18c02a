#pragma once
/// Rotation-minimising frames along a curve, for sweeping pipe cross-sections without the
/// twist and flips of Frenet frames: the double reflection method (Wang, Jüttler, Zheng and
/// Liu 2008, "Computation of rotation minimizing frames", ACM TOG 27(1)), fourth-order accurate.

#include <vector>

#include "core/curves/cubic_curve.h"

namespace viscera::core {

/// An orthonormal, right-handed frame on a curve: binormal = tangent × normal.
struct CurveFrame {
  Vec3 origin = Vec3::Zero();
  Vec3 tangent = Vec3::UnitZ();
  Vec3 normal = Vec3::UnitX();
  Vec3 binormal = Vec3::UnitY();
};

/// Frames at the increasing knot parameters `parameters` of `curve`. The first normal is
/// `initial_normal` made perpendicular to the first tangent (any perpendicular when it is zero
/// or parallel to the tangent). With `close_loop` on a closed curve whose parameters span the
/// whole loop, the remaining twist between the last and first frame is spread over the frames
/// in proportion to the knot parameter, so a swept tube closes without a seam. Throws
/// UsageError for an empty parameter list.
std::vector<CurveFrame> rotation_minimizing_frames(const CubicCurve& curve,
                                                   const std::vector<double>& parameters,
                                                   const Vec3& initial_normal = Vec3::Zero(),
                                                   bool close_loop = false);

/// A unit vector perpendicular to `direction`, deterministic: `hint` projected off `direction`
/// when that leaves a usable vector, otherwise the coordinate axis least aligned with it.
Vec3 perpendicular_to(const Vec3& direction, const Vec3& hint = Vec3::Zero());

}  // namespace viscera::core
