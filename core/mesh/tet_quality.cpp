#include "core/mesh/tet_quality.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>

namespace viscera::core {

TetShape tet_shape(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  TetShape shape;
  const Vec3 ab = b - a, ac = c - a, ad = d - a;
  const double six_volume = ab.dot(ac.cross(ad));
  shape.signed_volume = six_volume / 6.0;

  // Area vectors of the faces opposite each corner, all pointing outward for a positive tet.
  const std::array<Vec3, 4> p{a, b, c, d};
  std::array<Vec3, 4> face;
  face[0] = 0.5 * (c - b).cross(d - b);
  face[1] = 0.5 * (d - a).cross(c - a);
  face[2] = 0.5 * (b - a).cross(d - a);
  face[3] = 0.5 * (c - a).cross(b - a);
  if (six_volume < 0.0)
    for (auto& f : face)
      f = -f;

  // The dihedral angle along the edge shared by faces i and j is π minus the angle between
  // their outward normals.
  shape.min_dihedral_degrees = 180.0;
  shape.max_dihedral_degrees = 0.0;
  double area_sum = 0.0;
  for (int i = 0; i < 4; ++i) {
    area_sum += face[i].norm();
    for (int j = i + 1; j < 4; ++j) {
      const double ni = face[i].norm(), nj = face[j].norm();
      double angle = 0.0;
      if (ni > 0.0 && nj > 0.0) {
        const double cosine = std::clamp(face[i].dot(face[j]) / (ni * nj), -1.0, 1.0);
        angle = 180.0 - std::acos(cosine) * 180.0 / std::numbers::pi;
      }
      shape.min_dihedral_degrees = std::min(shape.min_dihedral_degrees, angle);
      shape.max_dihedral_degrees = std::max(shape.max_dihedral_degrees, angle);
    }
  }

  double shortest = kInf, longest = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const double length = (p[i] - p[j]).norm();
      shortest = std::min(shortest, length);
      longest = std::max(longest, length);
    }

  if (six_volume == 0.0 || shortest == 0.0) {
    shape.radius_edge_ratio = kInf;
    shape.aspect_ratio = kInf;
    return shape;
  }
  // Circumradius from the corner at a: |ab|²(ac×ad) + |ac|²(ad×ab) + |ad|²(ab×ac) / (2·6V).
  const Vec3 numerator = ab.squaredNorm() * ac.cross(ad) + ac.squaredNorm() * ad.cross(ab) +
                         ad.squaredNorm() * ab.cross(ac);
  const double circumradius = numerator.norm() / (2.0 * std::abs(six_volume));
  const double inradius = std::abs(six_volume) / (2.0 * area_sum);  // 3V / total area
  shape.radius_edge_ratio = circumradius / shortest;
  shape.aspect_ratio = longest / (2.0 * std::sqrt(6.0) * inradius);
  return shape;
}

TetQualityReport tet_quality(const TetMesh& mesh, const TetQualityOptions& options) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  TetQualityReport report;
  report.tets = mesh.tets.size();
  report.nodes = mesh.nodes.size();
  report.sliver_angle_degrees = options.sliver_angle_degrees;
  report.min_volume = mesh.tets.empty() ? kNaN : std::numeric_limits<double>::infinity();
  report.min_dihedral_degrees = 180.0;
  report.max_dihedral_degrees = 0.0;
  report.min_radius_edge_ratio = std::numeric_limits<double>::infinity();
  report.max_radius_edge_ratio = 0.0;
  report.max_aspect_ratio = 0.0;
  double radius_edge_sum = 0.0, aspect_sum = 0.0;
  std::size_t positive = 0;
  static constexpr double kHistogramEdges[4] = {5.0, 10.0, 20.0, 30.0};

  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const auto& tet = mesh.tets[t];
    const TetShape shape =
        tet_shape(mesh.nodes[tet[0]], mesh.nodes[tet[1]], mesh.nodes[tet[2]], mesh.nodes[tet[3]]);
    report.total_volume += shape.signed_volume;
    report.min_volume = std::min(report.min_volume, shape.signed_volume);
    if (shape.signed_volume <= 0.0 || !std::isfinite(shape.radius_edge_ratio)) {
      ++report.inverted;
      continue;
    }
    ++positive;
    if (shape.min_dihedral_degrees < report.min_dihedral_degrees) {
      report.min_dihedral_degrees = shape.min_dihedral_degrees;
      report.worst_tet = static_cast<int>(t);
    }
    report.max_dihedral_degrees = std::max(report.max_dihedral_degrees, shape.max_dihedral_degrees);
    report.min_radius_edge_ratio = std::min(report.min_radius_edge_ratio, shape.radius_edge_ratio);
    report.max_radius_edge_ratio = std::max(report.max_radius_edge_ratio, shape.radius_edge_ratio);
    report.max_aspect_ratio = std::max(report.max_aspect_ratio, shape.aspect_ratio);
    radius_edge_sum += shape.radius_edge_ratio;
    aspect_sum += shape.aspect_ratio;
    if (shape.min_dihedral_degrees < options.sliver_angle_degrees) ++report.slivers;
    int bin = 0;
    while (bin < 4 && shape.min_dihedral_degrees >= kHistogramEdges[bin])
      ++bin;
    ++report.min_dihedral_histogram[static_cast<std::size_t>(bin)];
  }
  if (positive == 0) {
    report.min_dihedral_degrees = report.max_dihedral_degrees = kNaN;
    report.min_radius_edge_ratio = report.max_radius_edge_ratio = kNaN;
    report.mean_radius_edge_ratio = report.mean_aspect_ratio = report.max_aspect_ratio = kNaN;
  } else {
    report.mean_radius_edge_ratio = radius_edge_sum / static_cast<double>(positive);
    report.mean_aspect_ratio = aspect_sum / static_cast<double>(positive);
  }
  return report;
}

void to_json(nlohmann::json& json, const TetQualityReport& report) {
  const auto number = [](double value) -> nlohmann::json {
    return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
  };
  json = {{"tets", report.tets},
          {"nodes", report.nodes},
          {"inverted", report.inverted},
          {"slivers", report.slivers},
          {"sliver_angle_degrees", report.sliver_angle_degrees},
          {"total_volume_m3", number(report.total_volume)},
          {"min_volume_m3", number(report.min_volume)},
          {"min_dihedral_degrees", number(report.min_dihedral_degrees)},
          {"max_dihedral_degrees", number(report.max_dihedral_degrees)},
          {"min_radius_edge_ratio", number(report.min_radius_edge_ratio)},
          {"mean_radius_edge_ratio", number(report.mean_radius_edge_ratio)},
          {"max_radius_edge_ratio", number(report.max_radius_edge_ratio)},
          {"mean_aspect_ratio", number(report.mean_aspect_ratio)},
          {"max_aspect_ratio", number(report.max_aspect_ratio)},
          {"worst_tet", report.worst_tet},
          {"min_dihedral_histogram",
           {{"below_5", report.min_dihedral_histogram[0]},
            {"5_to_10", report.min_dihedral_histogram[1]},
            {"10_to_20", report.min_dihedral_histogram[2]},
            {"20_to_30", report.min_dihedral_histogram[3]},
            {"30_and_above", report.min_dihedral_histogram[4]}}},
          {"valid", report.valid()}};
}

}  // namespace viscera::core
