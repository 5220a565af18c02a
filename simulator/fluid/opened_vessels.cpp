#include "simulator/fluid/opened_vessels.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "core/scenario/vessel_paths.h"

namespace viscera::sim::fluid {
namespace {

/// Where segment (a, b) crosses triangle (p, q, r): the fraction along the segment and the
/// crossing's barycentric coordinates (Möller & Trumbore 1997), or nothing when it misses or
/// runs parallel to the triangle's plane.
struct Crossing {
  double along = 0.0;
  core::Vec3 barycentric;
};

std::optional<Crossing> segment_crosses_triangle(const core::Vec3& a, const core::Vec3& b,
                                                 const core::Vec3& p, const core::Vec3& q,
                                                 const core::Vec3& r) {
  const core::Vec3 direction = b - a;
  const core::Vec3 e1 = q - p;
  const core::Vec3 e2 = r - p;
  const core::Vec3 h = direction.cross(e2);
  const double det = e1.dot(h);
  const double scale = e1.norm() * e2.norm() * direction.norm();
  if (!(std::abs(det) > 1e-12 * scale)) return std::nullopt;
  const core::Vec3 s = a - p;
  const double u = s.dot(h) / det;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const core::Vec3 qv = s.cross(e1);
  const double v = direction.dot(qv) / det;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  const double t = e2.dot(qv) / det;
  if (t < 0.0 || t > 1.0) return std::nullopt;
  return Crossing{t, core::Vec3(1.0 - u - v, u, v)};
}

/// A hollow vessel cut across: the cut's faces form a ring in the wall around the lumen and
/// none crosses the axis. Looks for the cut faces whose centroid lies within 1.5 radii of the
/// segment's axis and calls the lumen opened when they surround it (their unit directions out
/// from the axis average to less than half a unit: a one-sided cut beside a vessel averages
/// near one); the crossing is the face nearest the axis, at its centroid.
std::optional<Crossing> ring_around_lumen(const core::VesselTree& tree, int s,
                                          std::span<const core::Vec3> nodes,
                                          std::span<const core::Triangle> triangles,
                                          int& nearest_triangle) {
  const core::VesselSegment& segment = tree.segments[static_cast<std::size_t>(s)];
  if (!((segment.distal - segment.proximal).squaredNorm() > 0.0)) return std::nullopt;
  core::Vec3 outward_sum = core::Vec3::Zero();
  int around = 0;
  double best = std::numeric_limits<double>::infinity();
  Crossing crossing;
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
    const core::Triangle& tri = triangles[static_cast<std::size_t>(t)];
    const core::Vec3 c =
        (nodes[static_cast<std::size_t>(tri[0])] + nodes[static_cast<std::size_t>(tri[1])] +
         nodes[static_cast<std::size_t>(tri[2])]) /
        3.0;
    const core::VesselSegmentPoint at = core::nearest_point_on_segment(tree, s, c);
    if (at.projection < 0.0 || at.projection > 1.0) continue;  // beside the segment only
    const double distance = at.distance;
    if (distance > 1.5 * segment.radius || !(distance > 0.0)) continue;
    outward_sum += (c - at.point) / distance;
    ++around;
    if (distance < best) {
      best = distance;
      nearest_triangle = t;
      crossing = Crossing{at.along, core::Vec3::Constant(1.0 / 3.0)};
    }
  }
  if (around < 3 || outward_sum.norm() > 0.5 * around) return std::nullopt;
  return crossing;
}

/// 8 μ L / (π r⁴): the laminar resistance of a vessel of length `length` m and radius `radius` m.
double poiseuille_resistance(double length, double radius, double viscosity) {
  return 8.0 * viscosity * length / (std::numbers::pi * std::pow(radius, 4));
}

}  // namespace

std::vector<OpenedVessel> find_opened_vessels(const core::VesselTree& tree,
                                              std::span<const core::Vec3> nodes,
                                              std::span<const core::Triangle> triangles,
                                              const BleedingPhysiology& physiology) {
  const std::vector<std::vector<int>> paths = core::vessel_root_paths(tree);
  const std::vector<int> children = core::vessel_child_counts(tree);
  const double pressure =
      tree.kind == "venous" ? physiology.venous_pressure : physiology.arterial_pressure;
  const double mu = physiology.blood_viscosity;

  std::vector<OpenedVessel> opened;
  for (int s = 0; s < static_cast<int>(tree.segments.size()); ++s) {
    const core::VesselSegment& segment = tree.segments[static_cast<std::size_t>(s)];
    if (!(segment.radius > 0.0)) continue;  // a vessel without a lumen does not bleed
    std::optional<Crossing> nearest;
    int nearest_triangle = -1;
    for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
      const core::Triangle& tri = triangles[static_cast<std::size_t>(t)];
      const auto crossing = segment_crosses_triangle(
          segment.proximal, segment.distal, nodes[static_cast<std::size_t>(tri[0])],
          nodes[static_cast<std::size_t>(tri[1])], nodes[static_cast<std::size_t>(tri[2])]);
      if (crossing && (!nearest || crossing->along < nearest->along)) {
        nearest = crossing;
        nearest_triangle = t;
      }
    }
    if (!nearest) nearest = ring_around_lumen(tree, s, nodes, triangles, nearest_triangle);
    if (!nearest) continue;

    OpenedVessel vessel;
    vessel.segment = s;
    vessel.triangle = nearest_triangle;
    vessel.barycentric = nearest->barycentric;
    vessel.site = segment.proximal + nearest->along * (segment.distal - segment.proximal);
    vessel.along = nearest->along;
    vessel.radius = segment.radius;
    vessel.path = paths[static_cast<std::size_t>(s)];
    const core::VesselSegment& root = tree.segments[static_cast<std::size_t>(vessel.path.front())];
    double resistance =
        poiseuille_resistance((root.distal - root.proximal).norm(), root.radius, mu);  // feed
    for (std::size_t i = 0; i < vessel.path.size(); ++i) {
      const core::VesselSegment& on_path = tree.segments[static_cast<std::size_t>(vessel.path[i])];
      const double length = (on_path.distal - on_path.proximal).norm();
      const bool last = i + 1 == vessel.path.size();
      resistance +=
          poiseuille_resistance(last ? nearest->along * length : length, on_path.radius, mu);
      if (i > 0 && children[static_cast<std::size_t>(on_path.parent)] > 1) ++vessel.level;
    }
    vessel.conductance = resistance > 0.0 ? 1.0 / resistance : 0.0;
    vessel.pressure = pressure;
    opened.push_back(std::move(vessel));
  }
  return opened;
}

double triangles_area(std::span<const core::Vec3> nodes,
                      std::span<const core::Triangle> triangles) {
  double area = 0.0;
  for (const core::Triangle& t : triangles) {
    const core::Vec3& p = nodes[static_cast<std::size_t>(t[0])];
    area += 0.5 * (nodes[static_cast<std::size_t>(t[1])] - p)
                      .cross(nodes[static_cast<std::size_t>(t[2])] - p)
                      .norm();
  }
  return area;
}

}  // namespace viscera::sim::fluid
