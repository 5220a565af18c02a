#include "textures/triplanar_texture.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace viscera::textures {

using core::Vec3;

TriplanarTexture::TriplanarTexture(TextureMaps maps, double texture_scale, double sharpness)
    : maps_(std::move(maps)), scale_(texture_scale), sharpness_(sharpness) {
  if (maps_.albedo.empty() || maps_.albedo.channels != 3)
    throw core::UsageError("triplanar projection needs an RGB albedo map");
  if (!(texture_scale > 0.0)) throw core::UsageError("texture scale must be positive");
}

void TriplanarTexture::sample(const Image8& image, double u, double v, float* out) const {
  // Texel centres at (i + ½)/W; v runs up the image.
  const double x = (u - std::floor(u)) * image.width - 0.5;
  const double y = (1.0 - (v - std::floor(v))) * image.height - 0.5;
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const auto fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
  const auto wrap = [](int i, int n) { return ((i % n) + n) % n; };
  const int xs[2] = {wrap(x0, image.width), wrap(x0 + 1, image.width)};
  const int ys[2] = {wrap(y0, image.height), wrap(y0 + 1, image.height)};
  for (int c = 0; c < image.channels; ++c) {
    const auto at = [&](int i, int j) {
      return static_cast<float>(image.row(ys[j])[xs[i] * image.channels + c]);
    };
    out[c] = (at(0, 0) * (1 - fx) + at(1, 0) * fx) * (1 - fy) +
             (at(0, 1) * (1 - fx) + at(1, 1) * fx) * fy;
  }
}

SurfaceSample TriplanarTexture::shade(const Vec3& p, const Vec3& n, double /*texel_size*/) const {
  Vec3 weight = n.cwiseAbs().array().pow(sharpness_).matrix();
  weight /= weight.sum();
  const Vec3 q = p / scale_;
  SurfaceSample s;
  s.albedo = {0.0f, 0.0f, 0.0f};
  Vec3 normal = Vec3::Zero();
  double wet = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    if (weight[axis] < 1e-6) continue;
    // Projection along `axis`: texture u, v on the other two axes, u mirrored on the back side
    // so the texture never appears mirrored.
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    const double side = n[axis] < 0.0 ? -1.0 : 1.0;
    const double u = side * q[a], v = q[b];
    float rgb[3];
    sample(maps_.albedo, u, v, rgb);
    for (int k = 0; k < 3; ++k)
      s.albedo[k] += static_cast<float>(weight[axis]) * rgb[k];
    float specular = 127.5f;
    if (!maps_.specular.empty()) sample(maps_.specular, u, v, &specular);
    wet += weight[axis] * static_cast<double>(specular) / 255.0;
    Vec3 perturbed = n;
    if (!maps_.normal.empty()) {
      float tn[3];
      sample(maps_.normal, u, v, tn);
      // UDN: add the tangent normal's u, v tilt to the surface normal's components along the
      // projected axes.
      perturbed[a] += side * (static_cast<double>(tn[0]) / 127.5 - 1.0);
      perturbed[b] += static_cast<double>(tn[1]) / 127.5 - 1.0;
    }
    normal += weight[axis] * perturbed.normalized();
  }
  s.normal = normal.norm() > 0.0 ? Vec3(normal.normalized()) : n;
  s.wetness = static_cast<float>(std::clamp(wet, 0.0, 1.0));
  return s;
}

void bake_vertex_colors(core::SurfaceMesh& mesh, const SurfaceShader& shader) {
  if (mesh.normals.size() != mesh.vertices.size()) core::compute_vertex_normals(mesh);
  // The mean edge length is the footprint of one vertex sample.
  double edge = 0.0;
  for (const auto& t : mesh.triangles)
    edge += (mesh.vertices[t[1]] - mesh.vertices[t[0]]).norm();
  edge = mesh.triangles.empty() ? 1e-3 : edge / static_cast<double>(mesh.triangles.size());
  auto& r = mesh.vertex_attributes["albedo_r"];
  auto& g = mesh.vertex_attributes["albedo_g"];
  auto& b = mesh.vertex_attributes["albedo_b"];
  auto& w = mesh.vertex_attributes["wetness"];
  r.resize(mesh.vertices.size());
  g.resize(mesh.vertices.size());
  b.resize(mesh.vertices.size());
  w.resize(mesh.vertices.size());
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const SurfaceSample s = shader.shade(mesh.vertices[v], mesh.normals[v], edge);
    r[v] = std::clamp(static_cast<double>(s.albedo[0]) / 255.0, 0.0, 1.0);
    g[v] = std::clamp(static_cast<double>(s.albedo[1]) / 255.0, 0.0, 1.0);
    b[v] = std::clamp(static_cast<double>(s.albedo[2]) / 255.0, 0.0, 1.0);
    w[v] = static_cast<double>(s.wetness);
  }
}

}  // namespace viscera::textures
