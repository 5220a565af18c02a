#include "core/primitives/ball_primitive.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"
#include "core/primitives/icosphere.h"

namespace viscera::core {
namespace {

/// Wendland's ψ3,1: C2, positive definite in R³ (so on the sphere too), zero beyond r = 1.
double wendland(double r) {
  if (r >= 1.0) return 0.0;
  const double s = 1.0 - r;
  return s * s * s * s * (4.0 * r + 1.0);
}

}  // namespace

std::vector<Vec3> ball_control_directions(int control_level) {
  if (control_level < 0 || control_level > 2)
    throw UsageError("ball control level must be 0, 1 or 2");
  return make_icosphere(1.0, control_level).vertices;
}

BallPrimitive make_ball(const Vec3& center, double radius, int control_level, int subdivisions) {
  if (!(radius > 0.0) || !std::isfinite(radius)) throw UsageError("ball radius must be positive");
  if (!center.allFinite()) throw UsageError("ball centre must be finite");
  if (subdivisions < 0 || subdivisions > 7) throw UsageError("ball subdivisions must be in [0, 7]");
  BallPrimitive ball;
  ball.center = center;
  ball.radius = radius;
  ball.control_level = control_level;
  ball.subdivisions = subdivisions;
  for (const Vec3& d : ball_control_directions(control_level))
    ball.control_points.push_back(center + radius * d);
  return ball;
}

void check_ball(const BallPrimitive& ball, const std::string& what) {
  if (!(ball.radius > 0.0) || !std::isfinite(ball.radius))
    throw UsageError(what + ": ball radius must be positive");
  if (ball.control_level < 0 || ball.control_level > 2)
    throw UsageError(what + ": ball control level must be 0, 1 or 2");
  if (ball.subdivisions < 0 || ball.subdivisions > 7)
    throw UsageError(what + ": ball subdivisions must be in [0, 7]");
  const std::size_t expected = ball_control_directions(ball.control_level).size();
  if (ball.control_points.size() != expected) {
    throw UsageError(what + ": a level-" + std::to_string(ball.control_level) + " ball has " +
                     std::to_string(expected) + " control points, not " +
                     std::to_string(ball.control_points.size()));
  }
  for (std::size_t i = 0; i < ball.control_points.size(); ++i) {
    if (!ball.control_points[i].allFinite())
      throw UsageError(what + ": control point " + std::to_string(i) + " is not finite");
  }
}

BallShape::BallShape(const BallPrimitive& ball)
    : ball_(ball), directions_(ball_control_directions(ball.control_level)) {
  check_ball(ball, "ball");
  const auto n = static_cast<int>(directions_.size());
  // Support: three nearest-neighbour spacings, so an edit stays local on fine control sets,
  // but never more than the sphere's diameter.
  double spacing = 0.0;
  for (int i = 0; i < n; ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    for (int j = 0; j < n; ++j) {
      if (j != i)
        nearest = std::min(nearest, (directions_[static_cast<std::size_t>(i)] -
                                     directions_[static_cast<std::size_t>(j)])
                                        .norm());
    }
    spacing = std::max(spacing, nearest);
  }
  support_ = std::min(2.0, 3.0 * spacing);

  // [Φ P; Pᵀ 0] [w; a] = [δ; 0] with P = [1 d]: interpolates the displacements δ and keeps the
  // affine part exact (Wendland, Scattered Data Approximation, §8.5).
  Eigen::MatrixXd system = Eigen::MatrixXd::Zero(n + 4, n + 4);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n + 4, 3);
  for (int i = 0; i < n; ++i) {
    const Vec3& di = directions_[static_cast<std::size_t>(i)];
    for (int j = 0; j < n; ++j)
      system(i, j) = wendland((di - directions_[static_cast<std::size_t>(j)]).norm() / support_);
    system(i, n) = system(n, i) = 1.0;
    for (int c = 0; c < 3; ++c)
      system(i, n + 1 + c) = system(n + 1 + c, i) = di[c];
    const Vec3 displacement =
        ball.control_points[static_cast<std::size_t>(i)] - (ball.center + ball.radius * di);
    rhs.row(i) = displacement.transpose();
  }
  const Eigen::MatrixXd solution = system.fullPivLu().solve(rhs);
  weights_.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    weights_[static_cast<std::size_t>(i)] = solution.row(i).transpose();
  constant_ = solution.row(n).transpose();
  for (int c = 0; c < 3; ++c)
    linear_.col(c) = solution.row(n + 1 + c).transpose();
}

Vec3 BallShape::point(const Vec3& direction) const {
  const Vec3 d = direction.normalized();
  Vec3 displacement = constant_ + linear_ * d;
  for (std::size_t k = 0; k < directions_.size(); ++k) {
    const double phi = wendland((d - directions_[k]).norm() / support_);
    if (phi != 0.0) displacement += phi * weights_[k];
  }
  return ball_.center + ball_.radius * d + displacement;
}

SurfaceMesh tessellate_ball(const BallPrimitive& ball) {
  const BallShape shape(ball);
  SurfaceMesh mesh = make_icosphere(1.0, ball.subdivisions);
  for (auto& v : mesh.vertices)
    v = shape.point(v);
  compute_vertex_normals(mesh);
  return mesh;
}

}  // namespace viscera::core
