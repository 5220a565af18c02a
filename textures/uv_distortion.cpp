// Distortion measures of a parameterisation (Sander et al. 2001) and the usability check that
// decides whether a surface's own UVs can carry a baked texture.

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "textures/uv_atlas.h"

namespace viscera::textures {

UvDistortion measure_uv_distortion(const core::SurfaceMesh& mesh) {
  if (mesh.uvs.size() != mesh.vertices.size() || mesh.uvs.empty()) {
    throw core::UsageError("the mesh has no UVs to measure");
  }
  UvDistortion d;
  double area_3d = 0.0, area_2d = 0.0;
  struct TriangleMeasure {
    double a3, a2, stretch2, conformal;
  };
  std::vector<TriangleMeasure> measures;
  for (const auto& t : mesh.triangles) {
    const core::Vec3 &q1 = mesh.vertices[t[0]], &q2 = mesh.vertices[t[1]],
                     &q3 = mesh.vertices[t[2]];
    const core::Vec2 &p1 = mesh.uvs[t[0]], &p2 = mesh.uvs[t[1]], &p3 = mesh.uvs[t[2]];
    const double a3 = 0.5 * (q2 - q1).cross(q3 - q1).norm();
    const double a2 =
        0.5 * ((p2.x() - p1.x()) * (p3.y() - p1.y()) - (p3.x() - p1.x()) * (p2.y() - p1.y()));
    if (!(a3 > 0.0)) {
      ++d.degenerate;
      continue;
    }
    if (!(a2 > 0.0)) {
      ++d.flipped;
      continue;
    }
    // Partial derivatives of the surface point with respect to s and t (Sander et al. eq. 1).
    const core::Vec3 ss =
        (q1 * (p2.y() - p3.y()) + q2 * (p3.y() - p1.y()) + q3 * (p1.y() - p2.y())) / (2.0 * a2);
    const core::Vec3 st =
        (q1 * (p3.x() - p2.x()) + q2 * (p1.x() - p3.x()) + q3 * (p2.x() - p1.x())) / (2.0 * a2);
    const double a = ss.dot(ss), b = ss.dot(st), c = st.dot(st);
    const double root = std::sqrt((a - c) * (a - c) + 4.0 * b * b);
    const double big = std::sqrt(0.5 * (a + c + root)),
                 small = std::sqrt(std::max(0.5 * (a + c - root), 0.0));
    measures.push_back({a3, a2, 0.5 * (a + c),
                        small > 0.0 ? big / small : std::numeric_limits<double>::infinity()});
    area_3d += a3;
    area_2d += a2;
  }
  if (measures.empty()) return d;
  // Scale the map to the surface's area, so uniform texel density scores exactly 1.
  const double scale2 = area_2d / area_3d;
  double stretch = 0.0, conformal = 0.0;
  std::vector<std::pair<double, double>> density;  // (texel area per surface area, weight)
  for (const auto& m : measures) {
    stretch += m.a3 * m.stretch2 * scale2;
    conformal += m.a3 * m.conformal;
    d.max_conformal = std::max(d.max_conformal, m.conformal);
    density.emplace_back(m.a2 / m.a3 / scale2, m.a3);
  }
  d.l2_stretch = std::sqrt(stretch / area_3d);
  d.mean_conformal = conformal / area_3d;
  std::sort(density.begin(), density.end());
  const auto percentile = [&](double q) {
    double walked = 0.0;
    for (const auto& [value, weight] : density) {
      walked += weight;
      if (walked >= q * area_3d) return value;
    }
    return density.back().first;
  };
  d.area_ratio_p05 = percentile(0.05);
  d.area_ratio_p95 = percentile(0.95);
  return d;
}

bool has_usable_uvs(const core::SurfaceMesh& mesh) {
  if (mesh.uvs.size() != mesh.vertices.size() || mesh.triangles.empty()) return false;
  for (const auto& uv : mesh.uvs) {
    if (!uv.allFinite() || uv.x() < -1e-6 || uv.y() < -1e-6 || uv.x() > 1.0 + 1e-6 ||
        uv.y() > 1.0 + 1e-6) {
      return false;
    }
  }
  const UvDistortion d = measure_uv_distortion(mesh);
  if (d.flipped > 0 || !(d.l2_stretch < 2.0)) return false;
  // Overlap: rasterise triangle interiors at 512² and look for a texel claimed twice.
  constexpr int kRaster = 512;
  std::vector<int> owner(kRaster * kRaster, -1);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const core::Vec2 a = mesh.uvs[tri[0]] * kRaster, b = mesh.uvs[tri[1]] * kRaster,
                     c = mesh.uvs[tri[2]] * kRaster;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x(), b.x(), c.x()}))));
    const int x1 =
        std::min(kRaster - 1, static_cast<int>(std::ceil(std::max({a.x(), b.x(), c.x()}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y(), b.y(), c.y()}))));
    const int y1 =
        std::min(kRaster - 1, static_cast<int>(std::ceil(std::max({a.y(), b.y(), c.y()}))));
    const double area = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const core::Vec2 p(x + 0.5, y + 0.5);
        const double w0 =
            ((b.x() - p.x()) * (c.y() - p.y()) - (c.x() - p.x()) * (b.y() - p.y())) / area;
        const double w1 =
            ((c.x() - p.x()) * (a.y() - p.y()) - (a.x() - p.x()) * (c.y() - p.y())) / area;
        const double w2 = 1.0 - w0 - w1;
        // Strictly inside only: texels on a shared edge belong to both neighbours legitimately.
        if (w0 <= 1e-6 || w1 <= 1e-6 || w2 <= 1e-6) continue;
        int& o = owner[static_cast<std::size_t>(y) * kRaster + x];
        if (o >= 0 && o != static_cast<int>(t)) return false;
        o = static_cast<int>(t);
      }
    }
  }
  return true;
}

}  // namespace viscera::textures
