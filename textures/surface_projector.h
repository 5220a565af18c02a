#pragma once
/// Closest points on an organ surface (CGAL AABB tree), for keeping vessel turtles on the
/// surface and drawing surface points.

#include <memory>

#include "core/mesh/surface_mesh.h"
#include "core/random.h"

namespace viscera::textures {

/// A point on the surface with its smooth (vertex-interpolated) unit normal.
struct SurfacePoint {
  core::Vec3 point = core::Vec3::Zero();
  core::Vec3 normal = core::Vec3::UnitZ();
  int triangle = -1;
};

/// Closest-point queries against a triangle surface. Positions in m.
class SurfaceProjector {
 public:
  /// Copies what it needs from `mesh`; normals are computed when absent. Throws
  /// core::InputError for a mesh without triangles.
  explicit SurfaceProjector(const core::SurfaceMesh& mesh);
  ~SurfaceProjector();
  SurfaceProjector(const SurfaceProjector&) = delete;
  SurfaceProjector& operator=(const SurfaceProjector&) = delete;

  /// The surface point closest to p.
  SurfacePoint closest(const core::Vec3& p) const;
  /// A point drawn uniformly by area.
  SurfacePoint random_point(core::Rng& rng) const;
  /// Total area in m².
  double area() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace viscera::textures
