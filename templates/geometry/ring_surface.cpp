#include "templates/geometry/ring_surface.h"

#include <cmath>
#include <numbers>

#include "core/error.h"

namespace viscera::templates {
namespace {

/// Triangles between ring A (first index a0, n_a points) and ring B (b0, n_b), closing the loop.
void stitch(const std::vector<core::Vec3>& v, int a0, int n_a, int b0, int n_b,
            std::vector<core::Triangle>& triangles) {
  int i = 0, j = 0;
  const auto A = [&](int k) { return a0 + k % n_a; };
  const auto B = [&](int k) { return b0 + k % n_b; };
  while (i < n_a || j < n_b) {
    bool advance_a;
    if (i == n_a) {
      advance_a = false;
    } else if (j == n_b) {
      advance_a = true;
    } else {
      // Advance the ring whose next point makes the shorter diagonal.
      advance_a = (v[A(i + 1)] - v[B(j)]).squaredNorm() < (v[A(i)] - v[B(j + 1)]).squaredNorm();
    }
    if (advance_a) {
      triangles.push_back({A(i), A(i + 1), B(j)});
      ++i;
    } else {
      triangles.push_back({A(i), B(j + 1), B(j)});
      ++j;
    }
  }
}

}  // namespace

core::SurfaceMesh ring_surface(const core::Vec3& first_pole, const std::vector<Ring>& rings,
                               const core::Vec3& last_pole) {
  if (rings.empty()) throw core::UsageError("a ring surface needs at least one ring");
  core::SurfaceMesh mesh;
  mesh.vertices.push_back(first_pole);
  std::vector<int> start;
  for (const auto& ring : rings) {
    if (ring.size() < 3)
      throw core::UsageError("every ring of a ring surface needs at least 3 points");
    start.push_back(static_cast<int>(mesh.vertices.size()));
    mesh.vertices.insert(mesh.vertices.end(), ring.begin(), ring.end());
  }
  const int last = static_cast<int>(mesh.vertices.size());
  mesh.vertices.push_back(last_pole);

  const auto n = [&](std::size_t r) { return static_cast<int>(rings[r].size()); };
  for (int k = 0; k < n(0); ++k)
    mesh.triangles.push_back({0, start[0] + (k + 1) % n(0), start[0] + k});
  for (std::size_t r = 0; r + 1 < rings.size(); ++r) {
    stitch(mesh.vertices, start[r], n(r), start[r + 1], n(r + 1), mesh.triangles);
  }
  const std::size_t r = rings.size() - 1;
  for (int k = 0; k < n(r); ++k)
    mesh.triangles.push_back({last, start[r] + k, start[r] + (k + 1) % n(r)});

  if (core::enclosed_volume(mesh) < 0.0) {
    for (auto& t : mesh.triangles)
      std::swap(t[1], t[2]);
  }
  return mesh;
}

Ring ellipse_ring(const core::Vec3& centre, const core::Vec3& x_axis, const core::Vec3& y_axis,
                  double a, double b, int count) {
  // Arc length table over the parameter, inverted by linear interpolation.
  constexpr int kTable = 512;
  std::vector<double> length(kTable + 1, 0.0);
  const auto point = [&](double t) { return core::Vec2(a * std::cos(t), b * std::sin(t)); };
  for (int k = 1; k <= kTable; ++k) {
    const double t0 = 2.0 * std::numbers::pi * (k - 1) / kTable,
                 t1 = 2.0 * std::numbers::pi * k / kTable;
    length[k] = length[k - 1] + (point(t1) - point(t0)).norm();
  }
  Ring ring;
  ring.reserve(static_cast<std::size_t>(count));
  int k = 0;
  for (int i = 0; i < count; ++i) {
    const double target = length[kTable] * i / count;
    while (k < kTable && length[k + 1] < target)
      ++k;
    const double span = length[k + 1] - length[k];
    const double f = span > 0.0 ? (target - length[k]) / span : 0.0;
    const double t = 2.0 * std::numbers::pi * (k + f) / kTable;
    const core::Vec2 p = point(t);
    ring.push_back(centre + p.x() * x_axis + p.y() * y_axis);
  }
  return ring;
}

double ellipse_perimeter(double a, double b) {
  const double h = (a - b) * (a - b) / ((a + b) * (a + b));
  return std::numbers::pi * (a + b) * (1.0 + 3.0 * h / (10.0 + std::sqrt(4.0 - 3.0 * h)));
}

}  // namespace viscera::templates
