#include "core/mesh/surface_mesh.h"

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <utility>

#include "core/error.h"

namespace viscera::core {

double surface_area(const SurfaceMesh& mesh) {
  double area = 0.0;
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    area += 0.5 * (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm();
  }
  return area;
}

double enclosed_volume(const SurfaceMesh& mesh) {
  double volume = 0.0;
  for (const auto& t : mesh.triangles) {
    volume += mesh.vertices[t[0]].dot(mesh.vertices[t[1]].cross(mesh.vertices[t[2]]));
  }
  return volume / 6.0;
}

BoundingBox bounds(const SurfaceMesh& mesh) {
  BoundingBox box;
  for (const auto& v : mesh.vertices)
    box.add(v);
  return box;
}

void compute_vertex_normals(SurfaceMesh& mesh) {
  mesh.normals.assign(mesh.vertices.size(), Vec3::Zero());
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    // The cross product's length is twice the area: area weighting comes for free.
    const Vec3 n = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
    for (const int v : t)
      mesh.normals[v] += n;
  }
  for (auto& n : mesh.normals) {
    const double length = n.norm();
    n = length > 0.0 ? Vec3(n / length) : Vec3::UnitZ();
  }
}

bool is_closed_and_consistently_oriented(const SurfaceMesh& mesh) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : mesh.triangles) {
    for (int e = 0; e < 3; ++e) {
      if (++directed[{t[e], t[(e + 1) % 3]}] > 1) return false;
    }
  }
  for (const auto& [edge, count] : directed) {
    if (!directed.contains({edge.second, edge.first})) return false;
  }
  return !mesh.triangles.empty();
}

void check_surface_mesh(const SurfaceMesh& mesh, const std::string& what) {
  const auto n = static_cast<int>(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (!mesh.vertices[i].allFinite()) {
      throw InputError("vertex coordinate is not finite",
                       {what, "", "vertex " + std::to_string(i)});
    }
  }
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    for (const int v : mesh.triangles[i]) {
      if (v < 0 || v >= n) {
        throw InputError(
            "triangle refers to vertex " + std::to_string(v) + " of " + std::to_string(n),
            {what, "", "triangle " + std::to_string(i)});
      }
    }
  }
  if (!mesh.normals.empty() && mesh.normals.size() != mesh.vertices.size()) {
    throw InputError("normals array length differs from vertex count", {what, "", ""});
  }
  if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.vertices.size()) {
    throw InputError("UV array length differs from vertex count", {what, "", ""});
  }
  for (const auto& [name, values] : mesh.vertex_attributes) {
    if (values.size() != mesh.vertices.size()) {
      throw InputError("attribute length differs from vertex count", {what, "", name});
    }
  }
}

}  // namespace viscera::core
