#include "textures/texture_baker.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "textures/parallel_rows.h"

namespace viscera::textures {
namespace {

using core::Vec2;
using core::Vec3;

inline std::uint8_t to_byte(double value) {
  return static_cast<std::uint8_t>(std::clamp(value, 0.0, 255.0) + 0.5);
}

/// Per-triangle data the rasteriser needs.
struct BakeTriangle {
  Vec2 a, b, c;             ///< texel coordinates
  double area = 0.0;        ///< signed, texel units
  Vec3 tangent, bitangent;  ///< ∂p/∂u and ∂p/∂v, m per unit u and v
  double texel_size = 0.0;  ///< m per texel
};

/// Fills every empty texel that touches a filled one with the mean of its filled neighbours,
/// `passes` times (Jacobi order, so the result does not depend on traversal).
void dilate(TextureMaps& maps, std::vector<std::uint8_t>& filled, int passes) {
  const int w = maps.albedo.width, h = maps.albedo.height;
  for (int pass = 0; pass < passes; ++pass) {
    std::vector<std::uint8_t> next = filled;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * w + x;
        if (filled[i]) continue;
        int count = 0;
        double sum[7] = {0, 0, 0, 0, 0, 0, 0};
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if ((dx == 0 && dy == 0) || nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
            const std::size_t j = static_cast<std::size_t>(ny) * w + nx;
            if (!filled[j]) continue;
            ++count;
            for (int k = 0; k < 3; ++k)
              sum[k] += maps.albedo.pixels[3 * j + k];
            for (int k = 0; k < 3; ++k)
              sum[3 + k] += maps.normal.pixels[3 * j + k];
            sum[6] += maps.specular.pixels[j];
          }
        }
        if (count == 0) continue;
        for (int k = 0; k < 3; ++k)
          maps.albedo.pixels[3 * i + k] = to_byte(sum[k] / count);
        for (int k = 0; k < 3; ++k)
          maps.normal.pixels[3 * i + k] = to_byte(sum[3 + k] / count);
        maps.specular.pixels[i] = to_byte(sum[6] / count);
        next[i] = 1;
      }
    }
    filled = std::move(next);
  }
}

}  // namespace

TextureMaps bake_surface_texture(const core::SurfaceMesh& input, const SurfaceShader& shader,
                                 const BakeOptions& options, core::Progress& progress) {
  const int W = options.width, H = options.height;
  if (W < 8 || H < 8 || W > 16384 || H > 16384)
    throw core::UsageError("bake size must be between 8 and 16384");
  if (input.uvs.size() != input.vertices.size() || input.triangles.empty()) {
    throw core::UsageError("baking needs a mesh with one UV per vertex");
  }
  core::SurfaceMesh mesh = input;
  if (mesh.normals.size() != mesh.vertices.size()) core::compute_vertex_normals(mesh);

  std::vector<BakeTriangle> triangles(mesh.triangles.size());
  const auto texel_of = [&](const Vec2& uv) { return Vec2(uv.x() * W, (1.0 - uv.y()) * H); };
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    BakeTriangle& b = triangles[t];
    b.a = texel_of(mesh.uvs[tri[0]]);
    b.b = texel_of(mesh.uvs[tri[1]]);
    b.c = texel_of(mesh.uvs[tri[2]]);
    b.area = (b.b.x() - b.a.x()) * (b.c.y() - b.a.y()) - (b.c.x() - b.a.x()) * (b.b.y() - b.a.y());
    const Vec3 e1 = mesh.vertices[tri[1]] - mesh.vertices[tri[0]],
               e2 = mesh.vertices[tri[2]] - mesh.vertices[tri[0]];
    const Vec2 d1 = mesh.uvs[tri[1]] - mesh.uvs[tri[0]], d2 = mesh.uvs[tri[2]] - mesh.uvs[tri[0]];
    const double det = d1.x() * d2.y() - d2.x() * d1.y();
    if (det != 0.0) {
      b.tangent = (e1 * d2.y() - e2 * d1.y()) / det;
      b.bitangent = (e2 * d1.x() - e1 * d2.x()) / det;
    }
    const double area_3d = 0.5 * e1.cross(e2).norm();
    b.texel_size = b.area != 0.0 ? std::sqrt(area_3d / (0.5 * std::abs(b.area))) : 0.0;
  }
  // Triangles bucketed by bands of texel rows.
  constexpr int kBand = 16;
  std::vector<std::vector<int>> bands(static_cast<std::size_t>((H + kBand - 1) / kBand));
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const auto& b = triangles[t];
    if (b.area == 0.0 || b.texel_size == 0.0) continue;
    const int y0 =
        std::clamp(static_cast<int>(std::floor(std::min({b.a.y(), b.b.y(), b.c.y()}))), 0, H - 1);
    const int y1 =
        std::clamp(static_cast<int>(std::ceil(std::max({b.a.y(), b.b.y(), b.c.y()}))), 0, H - 1);
    for (int band = y0 / kBand; band <= y1 / kBand; ++band)
      bands[band].push_back(static_cast<int>(t));
  }

  TextureMaps maps;
  maps.albedo = Image8(W, H, 3);
  maps.normal = Image8(W, H, 3);
  maps.specular = Image8(W, H, 1);
  std::vector<std::uint8_t> filled(static_cast<std::size_t>(W) * H, 0);
  progress.begin_stage("baking textures", H);
  parallel_rows(
      H,
      [&](int begin, int end) {
        for (int y = begin; y < end; ++y) {
          progress.check_cancelled();
          for (const int t : bands[y / kBand]) {
            const auto& b = triangles[t];
            const auto& tri = mesh.triangles[t];
            const double py = y + 0.5;
            const int x0 =
                std::max(0, static_cast<int>(std::floor(std::min({b.a.x(), b.b.x(), b.c.x()}))));
            const int x1 =
                std::min(W - 1, static_cast<int>(std::ceil(std::max({b.a.x(), b.b.x(), b.c.x()}))));
            for (int x = x0; x <= x1; ++x) {
              const std::size_t i = static_cast<std::size_t>(y) * W + x;
              if (filled[i]) continue;  // the lower-numbered triangle owns a shared edge
              const double px = x + 0.5;
              const double w0 =
                  ((b.b.x() - px) * (b.c.y() - py) - (b.c.x() - px) * (b.b.y() - py)) / b.area;
              const double w1 =
                  ((b.c.x() - px) * (b.a.y() - py) - (b.a.x() - px) * (b.c.y() - py)) / b.area;
              const double w2 = 1.0 - w0 - w1;
              constexpr double kEdge = -1e-9;
              if (w0 < kEdge || w1 < kEdge || w2 < kEdge) continue;
              const Vec3 p = w0 * mesh.vertices[tri[0]] + w1 * mesh.vertices[tri[1]] +
                             w2 * mesh.vertices[tri[2]];
              Vec3 n =
                  w0 * mesh.normals[tri[0]] + w1 * mesh.normals[tri[1]] + w2 * mesh.normals[tri[2]];
              n = n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::UnitZ();
              const SurfaceSample s = shader.shade(p, n, b.texel_size);
              // Tangent frame: T along +u, B along +v, Gram-Schmidt against the shading normal.
              Vec3 T = b.tangent - b.tangent.dot(n) * n;
              T = T.norm() > 0.0 ? Vec3(T.normalized()) : n.unitOrthogonal();
              Vec3 B = n.cross(T);
              if (B.dot(b.bitangent) < 0.0) B = -B;
              const Vec3 local(s.normal.dot(T), s.normal.dot(B), s.normal.dot(n));
              for (int k = 0; k < 3; ++k)
                maps.albedo.pixels[3 * i + k] = to_byte(static_cast<double>(s.albedo[k]));
              for (int k = 0; k < 3; ++k)
                maps.normal.pixels[3 * i + k] = to_byte((local[k] + 1.0) * 127.5);
              maps.specular.pixels[i] = to_byte(static_cast<double>(s.wetness) * 255.0);
              filled[i] = 1;
            }
          }
          progress.step();
        }
      },
      options.threads);

  // Texels never reached keep neutral values: mean colour, flat normal, mean wetness.
  std::vector<std::uint8_t> inside = filled;
  dilate(maps, filled, options.gutter);
  double mean[4] = {0, 0, 0, 0};
  std::size_t count = 0;
  for (std::size_t i = 0; i < inside.size(); ++i) {
    if (!inside[i]) continue;
    for (int k = 0; k < 3; ++k)
      mean[k] += maps.albedo.pixels[3 * i + k];
    mean[3] += maps.specular.pixels[i];
    ++count;
  }
  for (std::size_t i = 0; i < filled.size(); ++i) {
    if (filled[i]) continue;
    for (int k = 0; k < 3; ++k)
      maps.albedo.pixels[3 * i + k] = count ? to_byte(mean[k] / count) : 0;
    maps.normal.pixels[3 * i + 0] = 128;
    maps.normal.pixels[3 * i + 1] = 128;
    maps.normal.pixels[3 * i + 2] = 255;
    maps.specular.pixels[i] = count ? to_byte(mean[3] / count) : 0;
  }
  return maps;
}

}  // namespace viscera::textures
