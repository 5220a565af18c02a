#pragma once
/// Geometric queries against a closed triangle surface through CGAL (AABB tree, Polygon Mesh
/// Processing): closest points, inside tests, ray hits, self-intersection and intersection
/// tests. The template code places pathologies on an organ's wall with them, and the variant
/// validation checks every generated surface with them.

#include <memory>
#include <optional>

#include "core/mesh/surface_mesh.h"

namespace viscera::templates {

/// The closest point of a surface to a query point.
struct SurfacePoint {
  core::Vec3 position = core::Vec3::Zero();
  core::Vec3 normal = core::Vec3::UnitZ();  ///< unit outward normal of the triangle hit
  int triangle = -1;
  double distance = 0.0;  ///< m from the query point
};

/// A closed, outward-oriented surface prepared for repeated queries.
class SurfaceQueries {
 public:
  /// Throws core::InputError naming `what` when the surface is not closed and consistently
  /// oriented.
  explicit SurfaceQueries(const core::SurfaceMesh& surface, const std::string& what = "surface");
  ~SurfaceQueries();
  SurfaceQueries(SurfaceQueries&&) noexcept;
  SurfaceQueries& operator=(SurfaceQueries&&) noexcept;

  SurfacePoint closest(const core::Vec3& p) const;
  /// True when p lies strictly inside the solid the surface bounds.
  bool inside(const core::Vec3& p) const;
  /// Distance in m along the unit `direction` from `origin` to the first triangle hit beyond
  /// `skip` m, if any.
  std::optional<double> ray_hit(const core::Vec3& origin, const core::Vec3& direction,
                                double skip = 0.0) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// True when two triangles of `surface` that share no vertex intersect (CGAL PMP).
bool self_intersects(const core::SurfaceMesh& surface);

/// True when the two closed surfaces intersect or one holds the other (CGAL PMP do_intersect
/// with volumes).
bool surfaces_intersect(const core::SurfaceMesh& a, const core::SurfaceMesh& b);

/// True when a triangle of `a` meets a triangle of `b`; a surface wholly inside the other does
/// not count (CGAL PMP do_intersect without the bounded-side test). A hole in a host's body
/// passes; a seated pathology that pierces the wall does not.
bool surfaces_cross(const core::SurfaceMesh& a, const core::SurfaceMesh& b);

}  // namespace viscera::templates
