#include "simulator/dynamics/vessel_wave_paths.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <unordered_map>

#include "core/error.h"
#include "core/scenario/vessel_paths.h"

namespace viscera::sim {
namespace {

/// Nearest-node queries over a uniform grid of cubic cells (m): search shells of growing
/// radius until no closer node can lie outside the searched cells.
class NearestNodeGrid {
 public:
  NearestNodeGrid(std::span<const core::Vec3> nodes, double cell) : nodes_(nodes), cell_(cell) {
    lower_ = nodes.front();
    upper_ = nodes.front();
    for (const auto& p : nodes) {
      lower_ = lower_.cwiseMin(p);
      upper_ = upper_.cwiseMax(p);
    }
    for (std::size_t i = 0; i < nodes.size(); ++i)
      cells_[key(coordinates(nodes[i]))].push_back(static_cast<int>(i));
    const core::Vec3 extent = (upper_ - lower_) / cell_;
    max_shell_ = static_cast<int>(std::ceil(extent.maxCoeff())) + 1;
  }

  /// Index of the node nearest to `p` (the lowest index among equals).
  int nearest(const core::Vec3& p) const {
    const std::array<int, 3> centre = coordinates(p.cwiseMax(lower_).cwiseMin(upper_));
    // Distance from p to the box of nodes: shells closer than that are empty by construction.
    const double outside = (p - p.cwiseMax(lower_).cwiseMin(upper_)).norm();
    int best = -1;
    double best_distance = std::numeric_limits<double>::infinity();
    for (int shell = 0; shell <= max_shell_; ++shell) {
      // Every node outside the shells searched so far is at least (shell − 1)·cell away from
      // the clamped point, and p is `outside` from it.
      if (best >= 0 && std::max(0, shell - 1) * cell_ > best_distance + outside) break;
      for (int i = -shell; i <= shell; ++i)
        for (int j = -shell; j <= shell; ++j)
          for (int k = -shell; k <= shell; ++k) {
            if (std::max({std::abs(i), std::abs(j), std::abs(k)}) != shell) continue;
            const auto it = cells_.find(key({centre[0] + i, centre[1] + j, centre[2] + k}));
            if (it == cells_.end()) continue;
            for (const int n : it->second) {
              const double d = (nodes_[static_cast<std::size_t>(n)] - p).norm();
              if (d < best_distance || (d == best_distance && n < best)) {
                best_distance = d;
                best = n;
              }
            }
          }
    }
    return best;
  }

 private:
  std::array<int, 3> coordinates(const core::Vec3& p) const {
    const core::Vec3 c = (p - lower_) / cell_;
    return {static_cast<int>(std::floor(c.x())), static_cast<int>(std::floor(c.y())),
            static_cast<int>(std::floor(c.z()))};
  }
  static std::int64_t key(const std::array<int, 3>& c) {
    return (static_cast<std::int64_t>(c[0]) * 2097152 + c[1]) * 2097152 + c[2];
  }

  std::span<const core::Vec3> nodes_;
  double cell_;
  core::Vec3 lower_, upper_;
  int max_shell_ = 0;
  std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

/// Distance from `p` to segment (a, b) and the clamped length along it from a.
std::pair<double, double> distance_to_axis(const core::Vec3& p, const core::Vec3& a,
                                           const core::Vec3& b) {
  const core::Vec3 axis = b - a;
  const double length = axis.norm();
  if (length <= 0.0) return {(p - a).norm(), 0.0};
  const double along = std::clamp((p - a).dot(axis) / length, 0.0, length);
  return {(p - (a + along / length * axis)).norm(), along};
}

}  // namespace

std::vector<double> proximal_arc_lengths(const core::VesselTree& tree) {
  const std::vector<std::vector<int>> paths = core::vessel_root_paths(tree);
  std::vector<double> arc(paths.size(), 0.0);
  for (std::size_t s = 0; s < paths.size(); ++s) {
    for (std::size_t i = 0; i + 1 < paths[s].size(); ++i) {
      const auto& ancestor = tree.segments[static_cast<std::size_t>(paths[s][i])];
      arc[s] += (ancestor.distal - ancestor.proximal).norm();
    }
  }
  return arc;
}

std::vector<PulseWallKnot> pulse_wall_knots(const core::VesselTree& tree,
                                            std::span<const core::Vec3> host_nodes,
                                            double spacing) {
  if (host_nodes.empty())
    throw core::InputError("vessel tree \"" + tree.id + "\": its host body has no nodes",
                           {"", "", tree.id});
  if (!(spacing > 0.0)) throw core::UsageError("pulse wall knots need a positive sampling spacing");
  const std::vector<double> arc = proximal_arc_lengths(tree);
  const NearestNodeGrid grid(host_nodes, spacing);
  // node → (distance to the axis, segment): the closest segment among those it is nearest to.
  std::map<int, std::pair<double, int>> owner;
  for (int s = 0; s < static_cast<int>(tree.segments.size()); ++s) {
    const auto& segment = tree.segments[static_cast<std::size_t>(s)];
    const double length = (segment.distal - segment.proximal).norm();
    const int samples = 1 + static_cast<int>(std::ceil(length / spacing));
    for (int k = 0; k < samples; ++k) {
      const double u = samples > 1 ? static_cast<double>(k) / (samples - 1) : 0.0;
      const core::Vec3 p = segment.proximal + u * (segment.distal - segment.proximal);
      const int node = grid.nearest(p);
      const double d = distance_to_axis(host_nodes[static_cast<std::size_t>(node)],
                                        segment.proximal, segment.distal)
                           .first;
      const auto it = owner.find(node);
      if (it == owner.end() || d < it->second.first ||
          (d == it->second.first && s < it->second.second))
        owner[node] = {d, s};
    }
  }
  std::vector<PulseWallKnot> knots;
  knots.reserve(owner.size());
  for (const auto& [node, closest] : owner) {
    const int s = closest.second;
    const auto& segment = tree.segments[static_cast<std::size_t>(s)];
    const core::Vec3& p = host_nodes[static_cast<std::size_t>(node)];
    const auto [distance, along] = distance_to_axis(p, segment.proximal, segment.distal);
    const core::Vec3 axis = segment.distal - segment.proximal;
    const core::Vec3 foot = axis.norm() > 0.0
                                ? core::Vec3(segment.proximal + along / axis.norm() * axis)
                                : segment.proximal;
    PulseWallKnot knot;
    knot.node = node;
    knot.segment = s;
    knot.arc = arc[static_cast<std::size_t>(s)] + along;
    const core::Vec3 radial = p - foot;
    if (distance > 1e-12 * std::max(1.0, axis.norm()))
      knot.direction = radial / radial.norm();
    else
      knot.direction =
          axis.norm() > 0.0 ? core::Vec3(axis.normalized().unitOrthogonal()) : core::Vec3::UnitX();
    knots.push_back(knot);
  }
  std::sort(knots.begin(), knots.end(), [](const PulseWallKnot& a, const PulseWallKnot& b) {
    return a.arc != b.arc ? a.arc < b.arc : a.node < b.node;
  });
  return knots;
}

}  // namespace viscera::sim
