#include "templates/geometry/surface_queries.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include "core/error.h"

namespace viscera::templates {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
namespace PMP = CGAL::Polygon_mesh_processing;

Point point(const core::Vec3& v) {
  return {v.x(), v.y(), v.z()};
}
core::Vec3 vec(const Point& p) {
  return {p.x(), p.y(), p.z()};
}

/// The surface as a CGAL mesh; nullopt when a triangle cannot be added (non-manifold).
std::optional<Mesh> to_cgal(const core::SurfaceMesh& surface) {
  Mesh mesh;
  std::vector<Mesh::Vertex_index> vertices;
  vertices.reserve(surface.vertices.size());
  for (const auto& v : surface.vertices)
    vertices.push_back(mesh.add_vertex(point(v)));
  for (const auto& t : surface.triangles) {
    if (mesh.add_face(vertices[static_cast<std::size_t>(t[0])],
                      vertices[static_cast<std::size_t>(t[1])],
                      vertices[static_cast<std::size_t>(t[2])]) == Mesh::null_face()) {
      return std::nullopt;
    }
  }
  return mesh;
}

}  // namespace

struct SurfaceQueries::Impl {
  Mesh mesh;
  core::SurfaceMesh surface;
  Tree tree;
  std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, Kernel>> side;
};

SurfaceQueries::SurfaceQueries(const core::SurfaceMesh& surface, const std::string& what)
    : impl_(std::make_unique<Impl>()) {
  if (!core::is_closed_and_consistently_oriented(surface)) {
    throw core::InputError(what + " is not a closed, consistently oriented surface");
  }
  auto mesh = to_cgal(surface);
  if (!mesh) throw core::InputError(what + " is not a manifold surface");
  impl_->mesh = std::move(*mesh);
  impl_->surface = surface;
  impl_->tree.insert(faces(impl_->mesh).first, faces(impl_->mesh).second, impl_->mesh);
  impl_->tree.accelerate_distance_queries();
  impl_->side = std::make_unique<CGAL::Side_of_triangle_mesh<Mesh, Kernel>>(impl_->tree);
}

SurfaceQueries::~SurfaceQueries() = default;
SurfaceQueries::SurfaceQueries(SurfaceQueries&&) noexcept = default;
SurfaceQueries& SurfaceQueries::operator=(SurfaceQueries&&) noexcept = default;

SurfacePoint SurfaceQueries::closest(const core::Vec3& p) const {
  const auto [hit, face] = impl_->tree.closest_point_and_primitive(point(p));
  SurfacePoint result;
  result.position = vec(hit);
  result.triangle = static_cast<int>(face.idx());
  const auto& t = impl_->surface.triangles[face.idx()];
  const auto& v = impl_->surface.vertices;
  result.normal = (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).normalized();
  result.distance = (result.position - p).norm();
  return result;
}

bool SurfaceQueries::inside(const core::Vec3& p) const {
  return (*impl_->side)(point(p)) == CGAL::ON_BOUNDED_SIDE;
}

std::optional<double> SurfaceQueries::ray_hit(const core::Vec3& origin, const core::Vec3& direction,
                                              double skip) const {
  const Kernel::Ray_3 ray(point(origin + skip * direction),
                          Kernel::Vector_3(direction.x(), direction.y(), direction.z()));
  std::vector<Tree::Intersection_and_primitive_id<Kernel::Ray_3>::Type> hits;
  impl_->tree.all_intersections(ray, std::back_inserter(hits));
  std::optional<double> nearest;
  for (const auto& [object, face] : hits) {
    if (const Point* p = boost::get<Point>(&object)) {
      const double d = (vec(*p) - origin).norm();
      if (d > skip && (!nearest || d < *nearest)) nearest = d;
    }
  }
  return nearest;
}

bool self_intersects(const core::SurfaceMesh& surface) {
  const auto mesh = to_cgal(surface);
  if (!mesh) return true;  // a non-manifold fan is as unusable as a crossing
  return PMP::does_self_intersect(*mesh);
}

bool surfaces_intersect(const core::SurfaceMesh& a, const core::SurfaceMesh& b) {
  const auto ma = to_cgal(a);
  const auto mb = to_cgal(b);
  if (!ma || !mb) return true;
  return PMP::do_intersect(*ma, *mb, CGAL::parameters::do_overlap_test_of_bounded_sides(true),
                           CGAL::parameters::do_overlap_test_of_bounded_sides(true));
}

bool surfaces_cross(const core::SurfaceMesh& a, const core::SurfaceMesh& b) {
  const auto ma = to_cgal(a);
  const auto mb = to_cgal(b);
  if (!ma || !mb) return true;
  return PMP::do_intersect(*ma, *mb, CGAL::parameters::do_overlap_test_of_bounded_sides(false),
                           CGAL::parameters::do_overlap_test_of_bounded_sides(false));
}

}  // namespace viscera::templates
