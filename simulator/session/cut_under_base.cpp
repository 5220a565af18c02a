#include "simulator/session/cut_under_base.h"

#include <algorithm>

#include "simulator/collision/penetration_depth.h"
#include "simulator/dynamics/body_topology.h"

namespace viscera::sim {

namespace {

constexpr double kAboveNode = 0.0001;  ///< m: a sweep through the node itself passes under it

/// True when segment a→b meets any triangle of `surface`.
bool segment_meets(const core::Vec3& a, const core::Vec3& b, const cutting::CutSurface& surface) {
  const core::Vec3 lo = a.cwiseMin(b), hi = a.cwiseMax(b);
  for (const core::Triangle& t : surface.triangles) {
    const core::Vec3 &p = surface.vertices[static_cast<std::size_t>(t[0])],
                     &q = surface.vertices[static_cast<std::size_t>(t[1])],
                     &r = surface.vertices[static_cast<std::size_t>(t[2])];
    if ((p.cwiseMax(q).cwiseMax(r).array() < lo.array()).any() ||
        (p.cwiseMin(q).cwiseMin(r).array() > hi.array()).any())
      continue;
    if (segment_triangle_intersection(a, b, p, q, r) >= 0.0) return true;
  }
  return false;
}

}  // namespace

std::vector<std::uint8_t> nodes_cut_under(const World& world, int body,
                                          const cutting::CutSurface& swept) {
  std::vector<std::uint8_t> held = world.held_nodes(body);
  const auto x = world.state().range(world.state().positions, body);
  const auto inverse = world.state().range(world.state().inverse_masses, body);
  core::Vec3 centre = core::Vec3::Zero(), base = core::Vec3::Zero();
  int held_count = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    centre += x[i];
    if (inverse[i] == 0.0) held[i] = 0;  // fixed, not held by another body: no hold to cut
    if (held[i] == 0) continue;
    base += x[i];
    ++held_count;
  }
  std::vector<std::uint8_t> under(x.size(), 0);
  if (held_count == 0 || swept.triangles.empty()) return under;
  centre /= static_cast<double>(x.size());
  base /= static_cast<double>(held_count);
  if ((base - centre).norm() <= 0.0) return under;
  const core::Vec3 down = (base - centre).normalized();
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (held[i] == 0) continue;
    if (segment_meets(x[i] - kAboveNode * down, x[i] + kUnderBaseDepth * down, swept)) under[i] = 1;
  }
  return under;
}

int release_cut_under(World& world, int body, const cutting::CutSurface& swept) {
  std::vector<std::uint8_t> under = nodes_cut_under(world, body, swept);
  const auto count = static_cast<int>(std::count(under.begin(), under.end(), std::uint8_t{1}));
  if (count == 0) return 0;
  const auto& mesh = world.models()[static_cast<std::size_t>(body)]->mesh;
  BodyTopology topology =
      unchanged_topology(mesh, world.state().range(world.state().positions, body));
  topology.released = std::move(under);
  world.topology_changed(body, topology);
  return count;
}

}  // namespace viscera::sim
