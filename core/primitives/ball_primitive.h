#pragma once
/// KisMo's "ball" object type (seed 001 §3.3: "three predefined object types (flat, pipe, ball)
/// are interactively modified to get the desired object shape"): a sphere that follows control
/// points sitting on it. Moving control points deforms the sphere through a smooth vector field
/// on the unit sphere — compactly supported Wendland ψ3,1 radial basis functions of the chordal
/// distance plus an affine part (Wendland 1995) — which interpolates every control point and
/// reproduces translations, rotations and scalings of all of them exactly. Positions in m.

#include <vector>

#include "core/mesh/surface_mesh.h"

namespace viscera::core {

/// A ball: centre, radius, and control points at the vertices of an icosphere of
/// `control_level` (12, 42 or 162 points for levels 0, 1, 2) in their current positions.
struct BallPrimitive {
  Vec3 center = Vec3::Zero();
  double radius = 0.03;              ///< m
  int control_level = 0;             ///< 0, 1 or 2
  std::vector<Vec3> control_points;  ///< m; at rest center + radius · direction
  int subdivisions = 4;              ///< tessellation: icosphere level 0–7, 20·4^s triangles

  bool operator==(const BallPrimitive&) const = default;
};

/// A ball at rest. Throws UsageError for a non-positive radius or levels out of range.
BallPrimitive make_ball(const Vec3& center, double radius, int control_level = 0,
                        int subdivisions = 4);

/// Unit directions of the control points of a level (icosphere vertex order).
std::vector<Vec3> ball_control_directions(int control_level);

/// Throws UsageError naming `what` when the ball's fields disagree (point count, radius, levels).
void check_ball(const BallPrimitive& ball, const std::string& what);

/// The deformation field of a ball, solved once for its control points.
class BallShape {
 public:
  /// Solves the interpolation system; throws UsageError via check_ball.
  explicit BallShape(const BallPrimitive& ball);
  /// The surface point in m in unit direction `direction` from the centre.
  Vec3 point(const Vec3& direction) const;

 private:
  BallPrimitive ball_;
  std::vector<Vec3> directions_;
  double support_ = 2.0;          ///< chordal support radius of the basis functions
  std::vector<Vec3> weights_;     ///< one vector weight per control point
  Vec3 constant_ = Vec3::Zero();  ///< affine part: constant_ + linear_ · direction
  Mat3 linear_ = Mat3::Zero();
};

/// Closed, outward-oriented tessellation of the ball: the icosphere of `ball.subdivisions`
/// mapped through the shape, with vertex normals and the icosphere's spherical UVs.
SurfaceMesh tessellate_ball(const BallPrimitive& ball);

}  // namespace viscera::core
