#include "exporters/surface_sanitizer.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace viscera::exporters {

std::size_t sanitize_surface(core::SurfaceMesh& surface, const std::string& what) {
  core::check_surface_mesh(surface, what);  // positions finite, indices and array sizes right
  std::size_t replaced = 0;
  if (surface.normals.empty()) {
    core::compute_vertex_normals(surface);
  } else {
    core::SurfaceMesh geometric;
    geometric.vertices = surface.vertices;
    geometric.triangles = surface.triangles;
    bool computed = false;
    for (std::size_t v = 0; v < surface.normals.size(); ++v) {
      core::Vec3& n = surface.normals[v];
      if (n.allFinite() && n.norm() > 1e-12) continue;
      if (!computed) {
        core::compute_vertex_normals(geometric);
        computed = true;
      }
      n = geometric.normals[v];
      ++replaced;
    }
  }
  for (core::Vec3& n : surface.normals) {
    const double length = n.norm();
    n = std::isfinite(length) && length > 1e-12 ? core::Vec3(n / length) : core::Vec3::UnitZ();
  }
  for (core::Vec2& uv : surface.uvs) {
    for (int c = 0; c < 2; ++c) {
      if (!std::isfinite(uv[c])) {
        uv[c] = 0.0;
        ++replaced;
      }
    }
  }
  for (const char* channel : {"albedo_r", "albedo_g", "albedo_b"}) {
    const auto found = surface.vertex_attributes.find(channel);
    if (found == surface.vertex_attributes.end()) continue;
    for (double& value : found->second) {
      if (!std::isfinite(value)) {
        value = 0.0;
        ++replaced;
      }
      value = std::clamp(value, 0.0, 1.0);
    }
  }
  return replaced;
}

}  // namespace viscera::exporters
