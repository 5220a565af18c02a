#include "simulator/dynamics/cavity_pressure.h"

namespace viscera::sim {

Vec3 CavitySurface::vertex(std::span<const Vec3> x, int v) const {
  const auto& n = nodes[static_cast<std::size_t>(v)];
  const auto& w = weights[static_cast<std::size_t>(v)];
  return w[0] * x[static_cast<std::size_t>(n[0])] + w[1] * x[static_cast<std::size_t>(n[1])] +
         w[2] * x[static_cast<std::size_t>(n[2])] + w[3] * x[static_cast<std::size_t>(n[3])];
}

CavitySurface cavity_surface(const core::SceneObject& object) {
  CavitySurface cavity;
  const auto marks = object.surface.vertex_attributes.find("cavity");
  if (marks == object.surface.vertex_attributes.end() || object.body.nodes.empty()) return cavity;
  const std::vector<double>& marked = marks->second;
  const std::size_t count = object.surface.vertices.size();
  if (marked.size() != count) return cavity;
  const bool embedded = !object.embedding.empty();
  if (!embedded && count > object.body.nodes.size()) return cavity;
  cavity.nodes.resize(count);
  cavity.weights.resize(count);
  for (std::size_t v = 0; v < count; ++v) {
    if (embedded) {
      const auto& tet = object.body.tets[static_cast<std::size_t>(object.embedding.tet[v])];
      cavity.nodes[v] = {tet[0], tet[1], tet[2], tet[3]};
      cavity.weights[v] = object.embedding.weights[v];
    } else {
      const int node = static_cast<int>(v);
      cavity.nodes[v] = {node, node, node, node};
      cavity.weights[v] = {1.0, 0.0, 0.0, 0.0};
    }
  }
  for (const core::Triangle& t : object.surface.triangles) {
    if (marked[static_cast<std::size_t>(t[0])] > 0.5 &&
        marked[static_cast<std::size_t>(t[1])] > 0.5 &&
        marked[static_cast<std::size_t>(t[2])] > 0.5)
      cavity.faces.push_back(t);
  }
  if (cavity.faces.empty()) return {};
  return cavity;
}

void add_pressure_load(const CavitySurface& cavity, double pressure, std::span<const Vec3> x,
                       std::span<Vec3> f) {
  if (pressure == 0.0) return;
  for (const core::Triangle& t : cavity.faces) {
    const Vec3 a = cavity.vertex(x, t[0]);
    const Vec3 b = cavity.vertex(x, t[1]);
    const Vec3 c = cavity.vertex(x, t[2]);
    const Vec3 share = (-pressure / 6.0) * (b - a).cross(c - a);
    for (const int v : t) {
      const auto& n = cavity.nodes[static_cast<std::size_t>(v)];
      const auto& w = cavity.weights[static_cast<std::size_t>(v)];
      for (int j = 0; j < 4; ++j)
        if (w[static_cast<std::size_t>(j)] != 0.0)
          f[static_cast<std::size_t>(n[static_cast<std::size_t>(j)])] +=
              w[static_cast<std::size_t>(j)] * share;
    }
  }
}

double cavity_volume(const CavitySurface& cavity, std::span<const Vec3> x, const Vec3& apex) {
  double six_volume = 0.0;
  for (const core::Triangle& t : cavity.faces) {
    const Vec3 a = cavity.vertex(x, t[0]) - apex;
    const Vec3 b = cavity.vertex(x, t[1]) - apex;
    const Vec3 c = cavity.vertex(x, t[2]) - apex;
    six_volume += a.dot(b.cross(c));
  }
  return -six_volume / 6.0;
}

}  // namespace viscera::sim
