#include "textures/surface_projector.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace viscera::textures {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Triangle3 = Kernel::Triangle_3;
using Iterator = std::vector<Triangle3>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Kernel::Point_3 to_cgal(const core::Vec3& p) {
  return {p.x(), p.y(), p.z()};
}

}  // namespace

struct SurfaceProjector::Impl {
  core::SurfaceMesh mesh;
  std::vector<Triangle3> triangles;
  std::vector<double> cumulative_area;
  std::unique_ptr<Tree> tree;

  SurfacePoint at(int t, const core::Vec3& p) const {
    const auto& tri = mesh.triangles[t];
    const core::Vec3 &a = mesh.vertices[tri[0]], &b = mesh.vertices[tri[1]],
                     &c = mesh.vertices[tri[2]];
    // Barycentric weights of p in the triangle, for the smooth normal.
    const core::Vec3 n = (b - a).cross(c - a);
    const double n2 = n.squaredNorm();
    core::Vec3 w(1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0);
    if (n2 > 0.0) {
      w.x() = n.dot((c - b).cross(p - b)) / n2;
      w.y() = n.dot((a - c).cross(p - c)) / n2;
      w.z() = 1.0 - w.x() - w.y();
    }
    SurfacePoint s;
    s.point = p;
    s.triangle = t;
    const core::Vec3 smooth =
        w.x() * mesh.normals[tri[0]] + w.y() * mesh.normals[tri[1]] + w.z() * mesh.normals[tri[2]];
    s.normal = smooth.norm() > 0.0 ? core::Vec3(smooth.normalized())
                                   : (n2 > 0.0 ? core::Vec3(n.normalized()) : core::Vec3::UnitZ());
    return s;
  }
};

SurfaceProjector::SurfaceProjector(const core::SurfaceMesh& mesh)
    : impl_(std::make_unique<Impl>()) {
  if (mesh.triangles.empty()) throw core::InputError("the surface has no triangles");
  impl_->mesh = mesh;
  if (impl_->mesh.normals.size() != mesh.vertices.size()) core::compute_vertex_normals(impl_->mesh);
  double total = 0.0;
  for (const auto& t : mesh.triangles) {
    impl_->triangles.emplace_back(to_cgal(mesh.vertices[t[0]]), to_cgal(mesh.vertices[t[1]]),
                                  to_cgal(mesh.vertices[t[2]]));
    total += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                       .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                       .norm();
    impl_->cumulative_area.push_back(total);
  }
  impl_->tree = std::make_unique<Tree>(impl_->triangles.cbegin(), impl_->triangles.cend());
  impl_->tree->accelerate_distance_queries();
}

SurfaceProjector::~SurfaceProjector() = default;

SurfacePoint SurfaceProjector::closest(const core::Vec3& p) const {
  const auto [point, primitive] = impl_->tree->closest_point_and_primitive(to_cgal(p));
  const int t = static_cast<int>(primitive - impl_->triangles.cbegin());
  return impl_->at(t, core::Vec3(point.x(), point.y(), point.z()));
}

SurfacePoint SurfaceProjector::random_point(core::Rng& rng) const {
  const double target = rng.uniform01() * impl_->cumulative_area.back();
  const auto it =
      std::upper_bound(impl_->cumulative_area.begin(), impl_->cumulative_area.end(), target);
  const int t = static_cast<int>(
      std::min<std::ptrdiff_t>(it - impl_->cumulative_area.begin(),
                               static_cast<std::ptrdiff_t>(impl_->triangles.size()) - 1));
  double u = rng.uniform01(), v = rng.uniform01();
  if (u + v > 1.0) {
    u = 1.0 - u;
    v = 1.0 - v;
  }
  const auto& tri = impl_->mesh.triangles[t];
  const core::Vec3& a = impl_->mesh.vertices[tri[0]];
  return impl_->at(
      t, a + u * (impl_->mesh.vertices[tri[1]] - a) + v * (impl_->mesh.vertices[tri[2]] - a));
}

double SurfaceProjector::area() const {
  return impl_->cumulative_area.back();
}

}  // namespace viscera::textures
