#pragma once
/// Triangle surface meshes: the visual surface of a scene object (DESIGN.md §3).

#include <map>
#include <string>
#include <vector>

#include "core/math_types.h"

namespace viscera::core {

/// An indexed triangle mesh with optional per-vertex normals, UVs and named scalar arrays.
/// Positions in m. Triangles are counter-clockwise seen from outside for closed surfaces.
struct SurfaceMesh {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;
  std::vector<Vec3> normals;  ///< unit normals per vertex, or empty
  std::vector<Vec2> uvs;      ///< texture coordinates per vertex, or empty
  std::map<std::string, std::vector<double>> vertex_attributes;  ///< each of vertices.size()

  bool operator==(const SurfaceMesh&) const = default;
};

/// Total area in m².
double surface_area(const SurfaceMesh& mesh);
/// Signed enclosed volume in m³ by the divergence theorem; positive for outward orientation.
double enclosed_volume(const SurfaceMesh& mesh);
/// Bounding box of the vertices.
BoundingBox bounds(const SurfaceMesh& mesh);
/// Area-weighted vertex normals, normalised; fills mesh.normals.
void compute_vertex_normals(SurfaceMesh& mesh);
/// True when every edge is shared by exactly two triangles with opposite directions.
bool is_closed_and_consistently_oriented(const SurfaceMesh& mesh);
/// Throws InputError naming `what` and the element when an index is out of range, an array has
/// the wrong length, or a coordinate is not finite.
void check_surface_mesh(const SurfaceMesh& mesh, const std::string& what);

}  // namespace viscera::core
