#include "simulator/session/wall_cut_depth.h"

#include <limits>

namespace viscera::sim {

namespace {
/// m: a ray through the wall that meets nothing within this has left the organ for good.
constexpr double kLongestWall = 0.1;
}  // namespace

WallCutGauge::WallCutGauge(int body, CavitySurface cavity)
    : body_(body), cavity_(std::move(cavity)) {}

std::optional<WallCut> WallCutGauge::measure(const World& world,
                                             const cutting::CutSurface& swept) const {
  if (cavity_.empty() || swept.vertices.empty()) return std::nullopt;
  const auto x = world.state().range(world.state().positions, body_);
  std::vector<core::Vec3> cavity_points(cavity_.nodes.size());
  for (std::size_t v = 0; v < cavity_points.size(); ++v)
    cavity_points[v] = cavity_.vertex(x, static_cast<int>(v));
  const SurfaceBvh cavity(cavity_.faces, cavity_points);
  const BodyView& wall = world.bodies()[static_cast<std::size_t>(body_)];
  const SurfaceBvh organ(wall.surface_faces(), x);

  std::optional<WallCut> deepest;
  // Per swept vertex: its depth into the wall (0 in the cavity) and the cavity's normal there.
  std::vector<double> depth(swept.vertices.size(), 0.0);
  std::vector<core::Vec3> facing(swept.vertices.size(), core::Vec3::Zero());
  for (std::size_t i = 0; i < swept.vertices.size(); ++i) {
    const core::Vec3& v = swept.vertices[i];
    const NearestPoint near = cavity.nearest(v);
    if (near.triangle < 0) continue;
    const core::Triangle& f = cavity_.faces[static_cast<std::size_t>(near.triangle)];
    const core::Vec3 a = cavity_points[static_cast<std::size_t>(f[0])];
    const core::Vec3 n = (cavity_points[static_cast<std::size_t>(f[1])] - a)
                             .cross(cavity_points[static_cast<std::size_t>(f[2])] - a)
                             .normalized();
    facing[i] = n;
    if ((v - near.point).dot(n) >= 0.0) continue;  // in the cavity, on the loop's side
    // Through the tissue from the cavity's wall to the organ's outer surface.
    const RayHit far = organ.cast(near.point - 1e-6 * n, -n, kLongestWall);
    const double thickness =
        far.triangle >= 0 ? far.distance + 1e-6 : std::numeric_limits<double>::infinity();
    WallCut cut;
    cut.depth = near.distance;
    cut.thickness = thickness;
    cut.perforated = near.distance >= thickness;
    if (cut.perforated) cut.depth = thickness;  // the wall ends there: the loop went through it
    depth[i] = cut.depth;
    const bool deeper = !deepest || (cut.perforated && !deepest->perforated) ||
                        (cut.perforated == deepest->perforated &&
                         cut.depth / cut.thickness > deepest->depth / deepest->thickness);
    if (deeper) deepest = cut;
  }
  if (!deepest) return deepest;
  for (const core::Triangle& t : swept.triangles) {
    const auto i = static_cast<std::size_t>(t[0]), j = static_cast<std::size_t>(t[1]),
               k = static_cast<std::size_t>(t[2]);
    const double mean = (depth[i] + depth[j] + depth[k]) / 3.0;
    if (mean <= 0.0) continue;
    const core::Vec3 area =
        0.5 * (swept.vertices[j] - swept.vertices[i]).cross(swept.vertices[k] - swept.vertices[i]);
    const core::Vec3 n = (facing[i] + facing[j] + facing[k]).normalized();
    deepest->removed_volume += std::abs(area.dot(n)) * mean;
  }
  return deepest;
}

}  // namespace viscera::sim
