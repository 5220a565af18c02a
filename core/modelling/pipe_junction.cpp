#include "core/modelling/pipe_junction.h"

// CGAL's fairing solves a sparse system with Eigen; this translation unit is compiled with
// CGAL_EIGEN3_ENABLED (core/CMakeLists.txt) so the default solver is available.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <limits>
#include <string>

#include "core/error.h"

namespace viscera::core {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using VertexIndex = Mesh::Vertex_index;
namespace PMP = CGAL::Polygon_mesh_processing;

Mesh to_cgal(const SurfaceMesh& surface, std::size_t tube) {
  Mesh mesh;
  std::vector<VertexIndex> vertices;
  vertices.reserve(surface.vertices.size());
  for (const Vec3& p : surface.vertices)
    vertices.push_back(mesh.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z())));
  for (const auto& t : surface.triangles) {
    if (mesh.add_face(vertices[static_cast<std::size_t>(t[0])],
                      vertices[static_cast<std::size_t>(t[1])],
                      vertices[static_cast<std::size_t>(t[2])]) == Mesh::null_face()) {
      throw InputError("pipe tube " + std::to_string(tube) + " is not a manifold surface");
    }
  }
  if (!CGAL::is_closed(mesh))
    throw InputError("pipe tube " + std::to_string(tube) + " is not closed");
  return mesh;
}

SurfaceMesh from_cgal(Mesh& mesh) {
  mesh.collect_garbage();
  SurfaceMesh surface;
  surface.vertices.reserve(mesh.number_of_vertices());
  for (const VertexIndex v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    surface.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (const auto f : mesh.faces()) {
    Triangle t{};
    int k = 0;
    for (const VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      t[static_cast<std::size_t>(k++)] = static_cast<int>(v.idx());
    surface.triangles.push_back(t);
  }
  return surface;
}

/// A point of an intersection curve and the fillet half-width around it.
struct SeamPoint {
  Vec3 position;
  double width;
};

Vec3 position(const Mesh& mesh, VertexIndex v) {
  const auto& p = mesh.point(v);
  return {p.x(), p.y(), p.z()};
}

/// True when `p` lies inside the band of any seam point.
bool in_band(const Vec3& p, const std::vector<SeamPoint>& seam) {
  for (const auto& s : seam) {
    if ((p - s.position).squaredNorm() < s.width * s.width) return true;
  }
  return false;
}

}  // namespace

SurfaceMesh join_tubes(const std::vector<JunctionTube>& tubes, double target_edge,
                       Progress& progress) {
  if (tubes.empty()) throw UsageError("no tubes to join");
  if (!(target_edge > 0.0)) throw UsageError("junction edge length must be positive");
  progress.begin_stage("joining pipes", static_cast<std::int64_t>(tubes.size()) + 1);
  Mesh result = to_cgal(tubes.front().surface, 0);
  auto seam_edge = result.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  auto blend = result.add_property_map<VertexIndex, double>("v:blend", -1.0).first;
  progress.step();

  for (std::size_t i = 1; i < tubes.size(); ++i) {
    Mesh tube = to_cgal(tubes[i].surface, i);
    if (PMP::does_self_intersect(tube)) {
      throw InputError("pipe tube " + std::to_string(i) +
                       " folds onto itself (its radius exceeds its bend radius somewhere)");
    }
    bool manifold = false;
    try {
      manifold = PMP::corefine_and_compute_union(
          result, tube, result, CGAL::parameters::edge_is_constrained_map(seam_edge),
          CGAL::parameters::default_values(), CGAL::parameters::edge_is_constrained_map(seam_edge));
    } catch (const std::exception& e) {
      throw InputError("pipe tube " + std::to_string(i) +
                       " cannot be joined to the tubes before it: " + e.what());
    }
    if (!manifold)
      throw InputError("joining pipe tube " + std::to_string(i) + " gives a non-manifold surface");
    // Vertices of the new intersection curve take this tube's fillet width.
    for (const auto e : result.edges()) {
      if (!seam_edge[e]) continue;
      for (const VertexIndex v : {result.vertex(e, 0), result.vertex(e, 1)}) {
        if (blend[v] < 0.0) blend[v] = tubes[i].blend_width;
      }
    }
    progress.step();
  }

  std::vector<SeamPoint> seam;
  for (const VertexIndex v : result.vertices()) {
    if (blend[v] > 0.0) seam.push_back({position(result, v), blend[v]});
  }
  if (!seam.empty()) {
    // Remesh the bands first: the corefinement leaves slivers along the seams, and fairing is
    // well conditioned only on well-shaped triangles.
    std::vector<Mesh::Face_index> band_faces;
    for (const auto f : result.faces()) {
      for (const VertexIndex v : CGAL::vertices_around_face(result.halfedge(f), result)) {
        if (in_band(position(result, v), seam)) {
          band_faces.push_back(f);
          break;
        }
      }
    }
    PMP::isotropic_remeshing(band_faces, target_edge, result,
                             CGAL::parameters::number_of_iterations(3));
    result.collect_garbage();
    std::vector<VertexIndex> band_vertices;
    for (const VertexIndex v : result.vertices()) {
      if (in_band(position(result, v), seam)) band_vertices.push_back(v);
    }
    if (!PMP::fair(result, band_vertices, CGAL::parameters::fairing_continuity(1))) {
      throw InputError("the smooth junctions of the pipes could not be computed (fairing failed)");
    }
  }
  progress.step();
  return from_cgal(result);
}

}  // namespace viscera::core
