#include "core/primitives/icosphere.h"

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <numbers>

#include "core/error.h"

namespace viscera::core {

SurfaceMesh make_icosphere(double radius, int subdivisions, const Vec3& center) {
  if (!(radius > 0.0)) throw UsageError("sphere radius must be positive");
  if (subdivisions < 0 || subdivisions > 7)
    throw UsageError("sphere subdivisions must be in [0, 7]");

  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> unit = {{-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0},
                            {0, -1, phi}, {0, 1, phi}, {0, -1, -phi}, {0, 1, -phi},
                            {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
  for (auto& v : unit)
    v.normalize();
  std::vector<Triangle> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};

  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<int, int>, int> midpoint_of;
    const auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto [it, inserted] = midpoint_of.try_emplace({key.first, key.second}, 0);
      if (inserted) {
        it->second = static_cast<int>(unit.size());
        unit.push_back((unit[a] + unit[b]).normalized());
      }
      return it->second;
    };
    std::vector<Triangle> refined;
    refined.reserve(faces.size() * 4);
    for (const auto& f : faces) {
      const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      refined.push_back({f[0], ab, ca});
      refined.push_back({f[1], bc, ab});
      refined.push_back({f[2], ca, bc});
      refined.push_back({ab, bc, ca});
    }
    faces = std::move(refined);
  }

  SurfaceMesh mesh;
  mesh.triangles = std::move(faces);
  mesh.vertices.reserve(unit.size());
  mesh.normals = unit;
  mesh.uvs.reserve(unit.size());
  for (const auto& n : unit) {
    mesh.vertices.push_back(center + radius * n);
    const double longitude = std::atan2(n.y(), n.x());
    const double u = (longitude < 0.0 ? longitude + 2.0 * std::numbers::pi : longitude) /
                     (2.0 * std::numbers::pi);
    mesh.uvs.emplace_back(u, std::acos(std::clamp(n.z(), -1.0, 1.0)) / std::numbers::pi);
  }
  return mesh;
}

double icosphere_edge_length(double radius, int subdivisions) {
  const SurfaceMesh mesh = make_icosphere(radius, subdivisions);
  double total = 0.0;
  for (const auto& t : mesh.triangles) {
    for (int e = 0; e < 3; ++e)
      total += (mesh.vertices[t[e]] - mesh.vertices[t[(e + 1) % 3]]).norm();
  }
  return total / (3.0 * static_cast<double>(mesh.triangles.size()));
}

int icosphere_subdivisions_for_edge(double radius, double edge_length) {
  if (!(edge_length > 0.0)) throw UsageError("target edge length must be positive");
  for (int s = 0; s < 7; ++s) {
    if (icosphere_edge_length(radius, s) <= edge_length) return s;
  }
  return 7;
}

}  // namespace viscera::core
