#include "textures/uv_atlas.h"

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "core/error.h"
#include "textures/uv_charts.h"

namespace viscera::textures {
namespace {

using core::Vec2;
using core::Vec3;
using Kernel = CGAL::Simple_cartesian<double>;
using CgalMesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace SMP = CGAL::Surface_mesh_parameterization;

/// One chart while the atlas is built: its mesh vertices and their flattened positions.
struct Chart {
  std::vector<int> triangles;
  std::vector<int> vertices;   ///< global vertex indices
  std::map<int, int> local;    ///< global → local
  std::vector<Vec2> uv;        ///< per local vertex; metres after scaling
  Vec2 size = Vec2::Zero();    ///< bounding box after rotation
  Vec2 offset = Vec2::Zero();  ///< placement in the atlas (metres)
};

double signed_area(const Vec2& a, const Vec2& b, const Vec2& c) {
  return 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y()));
}

int flipped_triangles(const core::SurfaceMesh& mesh, const Chart& chart) {
  int flipped = 0;
  for (const int t : chart.triangles) {
    const auto& tri = mesh.triangles[t];
    flipped += signed_area(chart.uv[chart.local.at(tri[0])], chart.uv[chart.local.at(tri[1])],
                           chart.uv[chart.local.at(tri[2])]) <= 0.0;
  }
  return flipped;
}

/// LSCM through CGAL; nullopt when CGAL refuses the chart or the solver fails.
std::optional<std::vector<Vec2>> lscm(const core::SurfaceMesh& mesh, const Chart& chart) {
  CgalMesh surface;
  for (const int v : chart.vertices) {
    const Vec3& p = mesh.vertices[v];
    surface.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z()));
  }
  for (const int t : chart.triangles) {
    const auto& tri = mesh.triangles[t];
    const auto face = surface.add_face(CgalMesh::Vertex_index(chart.local.at(tri[0])),
                                       CgalMesh::Vertex_index(chart.local.at(tri[1])),
                                       CgalMesh::Vertex_index(chart.local.at(tri[2])));
    if (face == CgalMesh::null_face()) return std::nullopt;
  }
  const auto border = CGAL::Polygon_mesh_processing::longest_border(surface).first;
  if (border == CgalMesh::null_halfedge()) return std::nullopt;
  auto uvmap = surface.add_property_map<CgalMesh::Vertex_index, Kernel::Point_2>("v:uv").first;
  if (SMP::parameterize(surface, SMP::LSCM_parameterizer_3<CgalMesh>(), border, uvmap) != SMP::OK) {
    return std::nullopt;
  }
  std::vector<Vec2> uv(chart.vertices.size());
  for (std::size_t i = 0; i < uv.size(); ++i) {
    const auto& p = uvmap[CgalMesh::Vertex_index(static_cast<CgalMesh::size_type>(i))];
    uv[i] = Vec2(p.x(), p.y());
    if (!uv[i].allFinite()) return std::nullopt;
  }
  return uv;
}

/// Orthogonal projection onto the plane of the chart's mean normal: the fallback flattening.
std::vector<Vec2> project(const core::SurfaceMesh& mesh, const Chart& chart) {
  Vec3 normal = Vec3::Zero();
  for (const int t : chart.triangles) {
    const auto& tri = mesh.triangles[t];
    normal += (mesh.vertices[tri[1]] - mesh.vertices[tri[0]])
                  .cross(mesh.vertices[tri[2]] - mesh.vertices[tri[0]]);
  }
  normal = normal.norm() > 0.0 ? Vec3(normal.normalized()) : Vec3::UnitZ();
  const Vec3 e1 = normal.unitOrthogonal(), e2 = normal.cross(e1);
  std::vector<Vec2> uv;
  for (const int v : chart.vertices)
    uv.emplace_back(mesh.vertices[v].dot(e1), mesh.vertices[v].dot(e2));
  return uv;
}

/// Mirrors a chart flattened the wrong way round, scales it to the surface's size and turns
/// its principal axis along u, so bounding boxes are tight.
void normalise_chart(const core::SurfaceMesh& mesh, Chart& chart) {
  double area_2d = 0.0, area_3d = 0.0;
  for (const int t : chart.triangles) {
    const auto& tri = mesh.triangles[t];
    area_2d += signed_area(chart.uv[chart.local[tri[0]]], chart.uv[chart.local[tri[1]]],
                           chart.uv[chart.local[tri[2]]]);
    area_3d += 0.5 * (mesh.vertices[tri[1]] - mesh.vertices[tri[0]])
                         .cross(mesh.vertices[tri[2]] - mesh.vertices[tri[0]])
                         .norm();
  }
  if (area_2d < 0.0) {
    for (auto& p : chart.uv)
      p.x() = -p.x();
    area_2d = -area_2d;
  }
  const double scale = area_2d > 0.0 ? std::sqrt(area_3d / area_2d) : 1.0;
  Vec2 mean = Vec2::Zero();
  for (auto& p : chart.uv)
    mean += p / static_cast<double>(chart.uv.size());
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
  for (const auto& p : chart.uv)
    covariance += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(covariance);
  Vec2 axis = eigen.eigenvectors().col(1);
  if (!axis.allFinite() || axis.norm() == 0.0) axis = Vec2::UnitX();
  const Eigen::Matrix2d rotation =
      (Eigen::Matrix2d() << axis.x(), axis.y(), -axis.y(), axis.x()).finished();
  Vec2 lo = Vec2::Constant(INFINITY), hi = Vec2::Constant(-INFINITY);
  for (auto& p : chart.uv) {
    p = scale * (rotation * (p - mean));
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  for (auto& p : chart.uv)
    p -= lo;
  chart.size = hi - lo;
}

/// Shelf packing with a gutter g around every chart and rows at most row_limit wide; returns
/// the side of the square it fits.
double pack_rows(std::vector<Chart>& charts, double g, double row_limit) {
  std::vector<std::size_t> order(charts.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return charts[a].size.y() > charts[b].size.y();
  });
  double x = 0.0, y = 0.0, shelf = 0.0, width = 0.0;
  for (const std::size_t i : order) {
    const double w = charts[i].size.x() + 2 * g, h = charts[i].size.y() + 2 * g;
    if (x > 0.0 && x + w > row_limit) {
      y += shelf;
      x = 0.0;
      shelf = 0.0;
    }
    charts[i].offset = Vec2(x + g, y + g);
    x += w;
    shelf = std::max(shelf, h);
    width = std::max(width, x);
  }
  return std::max(width, y + shelf);
}

/// Shelf packing trying a range of row widths and keeping the squarest (smallest side) layout.
double pack(std::vector<Chart>& charts, double g) {
  double total = 0.0, widest = 0.0;
  for (const auto& c : charts) {
    total += (c.size.x() + 2 * g) * (c.size.y() + 2 * g);
    widest = std::max(widest, c.size.x() + 2 * g);
  }
  double best_limit = widest, best_side = INFINITY;
  for (int k = 0; k <= 24; ++k) {
    const double limit = std::max(widest, std::sqrt(total) * (0.9 + 0.05 * k));
    const double side = pack_rows(charts, g, limit);
    if (side < best_side) {
      best_side = side;
      best_limit = limit;
    }
  }
  return pack_rows(charts, g, best_limit);
}

}  // namespace

UvAtlas build_uv_atlas(const core::SurfaceMesh& input, const UvAtlasOptions& options) {
  if (input.triangles.empty())
    throw core::InputError("cannot build a texture atlas for a mesh without triangles");
  if (options.resolution < 16 || options.gutter < 0)
    throw core::UsageError("atlas resolution ≥ 16 and gutter ≥ 0 needed");
  core::SurfaceMesh mesh = input;
  if (mesh.normals.size() != mesh.vertices.size()) core::compute_vertex_normals(mesh);

  const ChartSegmentation segmentation = segment_charts(mesh);
  std::vector<Chart> charts(static_cast<std::size_t>(segmentation.chart_count));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    Chart& chart = charts[segmentation.chart_of_triangle[t]];
    chart.triangles.push_back(static_cast<int>(t));
    for (const int v : mesh.triangles[t]) {
      if (chart.local.emplace(v, static_cast<int>(chart.vertices.size())).second)
        chart.vertices.push_back(v);
    }
  }
  UvAtlas atlas;
  for (auto& chart : charts) {
    const auto flattened = chart.triangles.size() > 1 ? lscm(mesh, chart) : std::nullopt;
    std::vector<Vec2> projected = project(mesh, chart);
    if (flattened) {
      chart.uv = *flattened;
      double area = 0.0;
      for (const int t : chart.triangles) {
        const auto& tri = mesh.triangles[t];
        area += signed_area(chart.uv[chart.local[tri[0]]], chart.uv[chart.local[tri[1]]],
                            chart.uv[chart.local[tri[2]]]);
      }
      if (area < 0.0) {
        for (auto& p : chart.uv)
          p.x() = -p.x();
      }
      const int lscm_flips = flipped_triangles(mesh, chart);
      Chart alternative = chart;
      alternative.uv = projected;
      if (lscm_flips > 0 && flipped_triangles(mesh, alternative) < lscm_flips) {
        chart.uv = std::move(projected);
        ++atlas.lscm_fallbacks;
      }
    } else {
      chart.uv = std::move(projected);
      if (chart.triangles.size() > 1) ++atlas.lscm_fallbacks;
    }
    normalise_chart(mesh, chart);
  }

  // The gutter is measured in texels of the final atlas, whose side depends on the packing.
  double area = 0.0;
  for (const auto& c : charts)
    area += c.size.x() * c.size.y();
  double gutter = options.gutter * std::sqrt(area) / options.resolution;
  double side = pack(charts, gutter);
  for (int round = 0; round < 8 && gutter < options.gutter * side / options.resolution; ++round) {
    gutter = 1.05 * options.gutter * side / options.resolution;
    side = pack(charts, gutter);
  }

  std::map<std::pair<int, int>, int> atlas_vertex;  // (original vertex, chart) → atlas vertex
  atlas.mesh.triangles.resize(mesh.triangles.size());
  for (auto& [name, values] : mesh.vertex_attributes)
    atlas.mesh.vertex_attributes[name];
  for (std::size_t c = 0; c < charts.size(); ++c) {
    const Chart& chart = charts[c];
    for (const int t : chart.triangles) {
      for (int k = 0; k < 3; ++k) {
        const int v = mesh.triangles[t][k];
        const auto [it, inserted] = atlas_vertex.emplace(
            std::pair{v, static_cast<int>(c)}, static_cast<int>(atlas.mesh.vertices.size()));
        if (inserted) {
          atlas.mesh.vertices.push_back(mesh.vertices[v]);
          atlas.mesh.normals.push_back(mesh.normals[v]);
          atlas.mesh.uvs.push_back((chart.uv[chart.local.at(v)] + chart.offset) / side);
          for (auto& [name, values] : mesh.vertex_attributes)
            atlas.mesh.vertex_attributes[name].push_back(values[v]);
          atlas.original_vertex.push_back(v);
        }
        atlas.mesh.triangles[t][k] = it->second;
      }
    }
  }
  atlas.chart_of_triangle = segmentation.chart_of_triangle;
  atlas.chart_count = segmentation.chart_count;
  return atlas;
}

}  // namespace viscera::textures
