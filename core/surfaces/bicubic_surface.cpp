#include "core/surfaces/bicubic_surface.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace viscera::core {
namespace {

/// Knot gaps of one direction averaged over the grid lines running that way (the averaged
/// chord-length parametrisation of surface interpolation, Piegl and Tiller §9.2.5), so every
/// row shares one set of u knots and every column one set of v knots.
std::vector<double> averaged_gaps(const std::vector<Vec3>& points, int lines, int count,
                                  bool closed, KnotSpacing spacing, bool along_rows,
                                  const char* direction) {
  const int segments = closed ? count : count - 1;
  std::vector<double> gaps(static_cast<std::size_t>(segments), 0.0);
  for (int line = 0; line < lines; ++line) {
    for (int k = 0; k < segments; ++k) {
      const int next = (k + 1) % count;
      const auto at = [&](int i) {
        return points[static_cast<std::size_t>(along_rows ? line * count + i : i * lines + line)];
      };
      const double chord = (at(next) - at(k)).norm();
      const double gap = spacing == KnotSpacing::Uniform       ? 1.0
                         : spacing == KnotSpacing::Centripetal ? std::sqrt(chord)
                                                               : chord;
      gaps[static_cast<std::size_t>(k)] += gap / lines;
    }
  }
  for (int k = 0; k < segments; ++k) {
    if (!(gaps[static_cast<std::size_t>(k)] > 0.0)) {
      throw UsageError(std::string("spline surface: grid ") + direction + " lines " +
                       std::to_string(k) + " and " + std::to_string((k + 1) % count) +
                       " coincide everywhere");
    }
  }
  return gaps;
}

double bernstein(int i, double t) {
  const double s = 1.0 - t;
  switch (i) {
    case 0:
      return s * s * s;
    case 1:
      return 3.0 * s * s * t;
    case 2:
      return 3.0 * s * t * t;
    default:
      return t * t * t;
  }
}

double bernstein_derivative(int i, double t) {
  const double s = 1.0 - t;
  switch (i) {
    case 0:
      return -3.0 * s * s;
    case 1:
      return 3.0 * s * s - 6.0 * s * t;
    case 2:
      return 6.0 * s * t - 3.0 * t * t;
    default:
      return 3.0 * t * t;
  }
}

}  // namespace

BicubicSurface::BicubicSurface(std::vector<Vec3> points, int rows, int cols, bool closed_u,
                               bool closed_v, KnotSpacing spacing)
    : points_(std::move(points)),
      rows_(rows),
      cols_(cols),
      closed_u_(closed_u),
      closed_v_(closed_v) {
  if (cols_ < (closed_u_ ? 3 : 2) || rows_ < (closed_v_ ? 3 : 2)) {
    throw UsageError("spline surface grid of " + std::to_string(rows_) + " × " +
                     std::to_string(cols_) + " points is too small");
  }
  if (points_.size() != static_cast<std::size_t>(rows_) * static_cast<std::size_t>(cols_)) {
    throw UsageError("spline surface grid has " + std::to_string(points_.size()) +
                     " points, expected rows × columns");
  }
  for (std::size_t i = 0; i < points_.size(); ++i) {
    if (!points_[i].allFinite())
      throw UsageError("spline surface grid point " + std::to_string(i) + " is not finite");
  }
  gaps_u_ = averaged_gaps(points_, rows_, cols_, closed_u_, spacing, true, "column");
  gaps_v_ = averaged_gaps(points_, cols_, rows_, closed_v_, spacing, false, "row");

  // Catmull-Rom along every row, then along every column of the resulting control points.
  net_cols_ = 3 * patches_u() + 1;
  std::vector<std::vector<Vec3>> row_nets;
  for (int r = 0; r < rows_; ++r) {
    const std::vector<Vec3> row(points_.begin() + r * cols_, points_.begin() + (r + 1) * cols_);
    row_nets.push_back(catmull_rom_bezier_net(row, gaps_u_, closed_u_));
  }
  const int net_rows = 3 * patches_v() + 1;
  net_.assign(static_cast<std::size_t>(net_rows * net_cols_), Vec3::Zero());
  for (int c = 0; c < net_cols_; ++c) {
    std::vector<Vec3> column(static_cast<std::size_t>(rows_));
    for (int r = 0; r < rows_; ++r)
      column[static_cast<std::size_t>(r)] =
          row_nets[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
    const std::vector<Vec3> column_net = catmull_rom_bezier_net(column, gaps_v_, closed_v_);
    for (int r = 0; r < net_rows; ++r)
      net_[static_cast<std::size_t>(r * net_cols_ + c)] = column_net[static_cast<std::size_t>(r)];
  }
}

BicubicSurface::Local BicubicSurface::locate(double u, double v) const {
  const auto wrap = [](double x, int patches, bool closed, int& p, double& t) {
    if (closed) {
      x = std::fmod(x, static_cast<double>(patches));
      if (x < 0.0) x += patches;
    } else {
      x = std::clamp(x, 0.0, static_cast<double>(patches));
    }
    p = std::min(static_cast<int>(std::floor(x)), patches - 1);
    t = x - p;
  };
  Local at{};
  wrap(u, patches_u(), closed_u_, at.pu, at.a);
  wrap(v, patches_v(), closed_v_, at.pv, at.b);
  return at;
}

Vec3 BicubicSurface::evaluate(const Local& at, int du, int dv) const {
  Vec3 sum = Vec3::Zero();
  for (int b = 0; b < 4; ++b) {
    const double wv = dv ? bernstein_derivative(b, at.b) : bernstein(b, at.b);
    for (int a = 0; a < 4; ++a) {
      const double wu = du ? bernstein_derivative(a, at.a) : bernstein(a, at.a);
      sum += wu * wv * net_[static_cast<std::size_t>((3 * at.pv + b) * net_cols_ + 3 * at.pu + a)];
    }
  }
  if (du) sum /= gaps_u_[static_cast<std::size_t>(at.pu)];
  if (dv) sum /= gaps_v_[static_cast<std::size_t>(at.pv)];
  return sum;
}

Vec3 BicubicSurface::point(double u, double v) const {
  return evaluate(locate(u, v), 0, 0);
}
Vec3 BicubicSurface::derivative_u(double u, double v) const {
  return evaluate(locate(u, v), 1, 0);
}
Vec3 BicubicSurface::derivative_v(double u, double v) const {
  return evaluate(locate(u, v), 0, 1);
}

Vec3 BicubicSurface::normal(double u, double v) const {
  const double scale = 1.0 + point(u, v).norm();
  // At a pole one derivative vanishes: step a little into the surface, where the normal has
  // its one-sided limit.
  for (const double step : {0.0, 1e-4, -1e-4, 1e-3, -1e-3}) {
    for (const bool along_v : {true, false}) {
      const double uu = along_v ? u : u + step, vv = along_v ? v + step : v;
      const Vec3 n = derivative_u(uu, vv).cross(derivative_v(uu, vv));
      if (n.norm() > 1e-12 * scale * scale) return n.normalized();
    }
  }
  return Vec3::UnitZ();
}

std::array<Vec3, 16> BicubicSurface::patch(int pu, int pv) const {
  std::array<Vec3, 16> control;
  for (int b = 0; b < 4; ++b)
    for (int a = 0; a < 4; ++a)
      control[static_cast<std::size_t>(a + 4 * b)] =
          net_[static_cast<std::size_t>((3 * pv + b) * net_cols_ + 3 * pu + a)];
  return control;
}

SurfaceSamples sample_surface(const BicubicSurface& surface,
                              const SurfaceTessellation& tessellation) {
  if (tessellation.u_steps_per_patch < 1 || tessellation.v_steps_per_patch < 1) {
    throw UsageError("surface tessellation needs at least one step per patch");
  }
  SurfaceSamples samples;
  const int nu = surface.patches_u() * tessellation.u_steps_per_patch;
  const int nv = surface.patches_v() * tessellation.v_steps_per_patch;
  samples.columns = surface.closed_u() ? nu : nu + 1;
  samples.rows = surface.closed_v() ? nv : nv + 1;
  const auto count = static_cast<std::size_t>(samples.rows * samples.columns);
  samples.positions.reserve(count);
  samples.normals.reserve(count);
  samples.uvs.reserve(count);
  for (int r = 0; r < samples.rows; ++r) {
    const double v = static_cast<double>(r) / tessellation.v_steps_per_patch;
    for (int c = 0; c < samples.columns; ++c) {
      const double u = static_cast<double>(c) / tessellation.u_steps_per_patch;
      samples.positions.push_back(surface.point(u, v));
      samples.normals.push_back(surface.normal(u, v));
      samples.uvs.emplace_back(u / surface.patches_u(), v / surface.patches_v());
    }
  }
  return samples;
}

std::vector<Triangle> sample_grid_triangles(int rows, int columns, bool closed_u, bool closed_v) {
  std::vector<Triangle> triangles;
  const int cells_u = closed_u ? columns : columns - 1;
  const int cells_v = closed_v ? rows : rows - 1;
  triangles.reserve(static_cast<std::size_t>(2 * cells_u * cells_v));
  for (int r = 0; r < cells_v; ++r) {
    const int r1 = (r + 1) % rows;
    for (int c = 0; c < cells_u; ++c) {
      const int c1 = (c + 1) % columns;
      const int p00 = r * columns + c, p01 = r * columns + c1, p10 = r1 * columns + c,
                p11 = r1 * columns + c1;
      triangles.push_back({p00, p01, p10});
      triangles.push_back({p01, p11, p10});
    }
  }
  return triangles;
}

SurfaceMesh tessellate(const BicubicSurface& surface, const SurfaceTessellation& tessellation) {
  SurfaceSamples samples = sample_surface(surface, tessellation);
  SurfaceMesh mesh;
  mesh.triangles =
      sample_grid_triangles(samples.rows, samples.columns, surface.closed_u(), surface.closed_v());
  mesh.vertices = std::move(samples.positions);
  mesh.normals = std::move(samples.normals);
  mesh.uvs = std::move(samples.uvs);
  return mesh;
}

}  // namespace viscera::core
