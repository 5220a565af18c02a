#include "importers/meshing/closed_surface_repair.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "core/error.h"

namespace viscera::importers {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

void check_finite(const core::SurfaceMesh& mesh, const std::string& what) {
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (!mesh.vertices[v].allFinite()) {
      throw core::InputError("the surface has a non-finite coordinate (NaN or infinity)",
                             {what, "", "vertex " + std::to_string(v)});
    }
  }
}

core::SurfaceMesh to_surface(const Mesh& mesh) {
  core::SurfaceMesh out;
  std::vector<int> index(mesh.number_of_vertices() + mesh.number_of_removed_vertices(), -1);
  for (const auto v : mesh.vertices()) {
    index[v.idx()] = static_cast<int>(out.vertices.size());
    const Point& p = mesh.point(v);
    out.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (const auto f : mesh.faces()) {
    core::Triangle t{};
    int c = 0;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      if (c < 3) t[static_cast<std::size_t>(c++)] = index[v.idx()];
    out.triangles.push_back(t);
  }
  return out;
}

/// Corners of each face, rotated so the smallest comes first: equal lists mean equal orientation.
std::vector<core::Triangle> oriented_faces(const Mesh& mesh) {
  std::vector<core::Triangle> faces;
  for (const auto f : mesh.faces()) {
    core::Triangle t{};
    int c = 0;
    for (const auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      if (c < 3) t[static_cast<std::size_t>(c++)] = static_cast<int>(v.idx());
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    faces.push_back(t);
  }
  return faces;
}

std::size_t count_self_intersections(const Mesh& mesh) {
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
  PMP::self_intersections<CGAL::Parallel_if_available_tag>(faces(mesh), mesh,
                                                           std::back_inserter(pairs));
  return pairs.size();
}

}  // namespace

SurfaceRepairReport repair_closed_surface(core::SurfaceMesh& surface, const std::string& what) {
  check_finite(surface, what);
  if (surface.triangles.empty()) {
    throw core::ValidationError("the surface has no triangles", {what, "", ""});
  }
  SurfaceRepairReport report;
  std::vector<Point> points;
  points.reserve(surface.vertices.size());
  for (const auto& v : surface.vertices)
    points.emplace_back(v.x(), v.y(), v.z());
  std::vector<std::vector<std::size_t>> polygons;
  polygons.reserve(surface.triangles.size());
  for (const auto& t : surface.triangles) {
    polygons.push_back({static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]),
                        static_cast<std::size_t>(t[2])});
  }
  const std::size_t before = points.size() + polygons.size();
  PMP::repair_polygon_soup(points, polygons);
  report.merged_vertices = before - points.size() - polygons.size();
  if (polygons.empty()) {
    throw core::ValidationError("the surface has only degenerate triangles", {what, "", ""});
  }
  const std::size_t soup_points = points.size();
  PMP::orient_polygon_soup(points, polygons);
  report.split_non_manifold_vertices = points.size() - soup_points;
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  report.split_non_manifold_vertices += PMP::duplicate_non_manifold_vertices(mesh);

  std::vector<Mesh::Halfedge_index> borders;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(borders));
  for (const auto h : borders) {
    std::vector<Mesh::Face_index> patch;
    PMP::triangulate_hole(mesh, h, std::back_inserter(patch));
    ++report.filled_holes;
  }
  if (!CGAL::is_closed(mesh)) {
    throw core::ValidationError("the surface has holes that could not be closed", {what, "", ""});
  }
  // Self-intersections are refused, not repaired (see the header): callers that can make the
  // surface another way (label_surface: a larger decimation budget) do so.
  if (const std::size_t pairs = count_self_intersections(mesh); pairs > 0) {
    throw core::ValidationError(
        "the surface intersects itself (" + std::to_string(pairs) + " pairs of triangles cross)",
        {what, "", ""});
  }
  const auto faces_before = oriented_faces(mesh);
  PMP::orient_to_bound_a_volume(mesh);
  report.reoriented = oriented_faces(mesh) != faces_before;
  surface = to_surface(mesh);
  return report;
}

void check_closed_surface(const core::SurfaceMesh& surface, const std::string& what) {
  check_finite(surface, what);
  if (surface.triangles.empty()) {
    throw core::ValidationError("the surface has no triangles", {what, "", ""});
  }
  if (!core::is_closed_and_consistently_oriented(surface)) {
    throw core::ValidationError(
        "the surface is not watertight: an edge is not shared by exactly two triangles with "
        "opposite directions",
        {what, "", ""});
  }
  std::vector<Point> points;
  for (const auto& v : surface.vertices)
    points.emplace_back(v.x(), v.y(), v.z());
  std::vector<std::vector<std::size_t>> polygons;
  for (const auto& t : surface.triangles) {
    polygons.push_back({static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]),
                        static_cast<std::size_t>(t[2])});
  }
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    throw core::ValidationError("the surface is not manifold: a vertex pinches two sheets",
                                {what, "", ""});
  }
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if (const std::size_t pairs = count_self_intersections(mesh); pairs > 0) {
    throw core::ValidationError(
        "the surface intersects itself: " + std::to_string(pairs) + " pairs of triangles cross",
        {what, "", ""});
  }
  Mesh oriented = mesh;
  PMP::orient_to_bound_a_volume(oriented);
  if (oriented_faces(oriented) != oriented_faces(mesh)) {
    throw core::ValidationError("the surface is not oriented outward", {what, "", ""});
  }
}

}  // namespace viscera::importers
