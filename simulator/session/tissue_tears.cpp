#include "simulator/session/tissue_tears.h"

#include <algorithm>
#include <string>

#include "core/error.h"
#include "simulator/cutting/cut_surface.h"
#include "simulator/cutting/hybrid_cut.h"
#include "simulator/dynamics/authored_terms.h"
#include "simulator/session/cut_topology.h"

namespace viscera::sim {

TissueTears::TissueTears(const World& world, std::vector<int> bodies)
    : bodies_(std::move(bodies)), made_by_crack_(world.models().size()) {
  seen_ = tear_count(world.terms());
}

bool TissueTears::tears(int body) const {
  return std::find(bodies_.begin(), bodies_.end(), body) != bodies_.end();
}

void TissueTears::follow(World& world, double time, std::vector<SessionEvent>& events) {
  if (tear_count(world.terms()) <= seen_) return;
  const std::vector<TearEvent> all = tears_of(world.terms());
  const std::vector<TearEvent> fresh(all.begin() + static_cast<std::ptrdiff_t>(seen_), all.end());
  for (const TearEvent& tear : fresh) {
    const int b = world.body_index(tear.body);
    if (b < 0 || !tears(b)) continue;
    auto& made = made_by_crack_[static_cast<std::size_t>(b)];
    const auto crack_made = [&](int node) {
      return static_cast<std::size_t>(node) < made.size() && made[static_cast<std::size_t>(node)];
    };
    const std::pair<int, int> link{std::min(tear.node_a, tear.node_b),
                                   std::max(tear.node_a, tear.node_b)};
    if (crack_made(link.first) || crack_made(link.second) || !split_.insert({b, link}).second)
      continue;
    const BodyModel& model = *world.models()[static_cast<std::size_t>(b)];
    const auto positions = world.state().range(world.state().positions, b);
    if (static_cast<std::size_t>(link.second) >= positions.size()) continue;  // an older mesh's
    const std::vector<core::Vec3> current(positions.begin(), positions.end());
    const core::Vec3 a = current[static_cast<std::size_t>(link.first)];
    const core::Vec3 c = current[static_cast<std::size_t>(link.second)];
    const double length = (c - a).norm();
    if (!(length > 0.0)) continue;
    const core::Vec3 along = (c - a) / length;
    cutting::TopologyChange change;
    try {
      const cutting::CutSurface crack = cutting::planar_cut_surface(
          0.5 * (a + c), along, along.unitOrthogonal(), length, length, 2);
      change = visible_ != nullptr ? visible_->cut(b, model.mesh, current, crack, {})
                                   : cutting::hybrid_cut(model.mesh, current, crack);
    } catch (const core::InputError&) {
      continue;  // a crack the cut refuses (a degenerate neighbourhood) stays a recorded tear
    }
    if (!change.changed) continue;
    const std::size_t before = positions.size();
    world.topology_changed(b, topology_of_cut(change, world.held_nodes(b)));
    made.resize(change.mesh.nodes.size(), 0);
    for (std::size_t v = before; v < made.size(); ++v)
      made[v] = 1;
    events.push_back({time, "tissue-torn-apart",
                      model.name + " tore apart between knots " + std::to_string(link.first) +
                          " and " + std::to_string(link.second) + " (" +
                          std::to_string(change.statistics.nodes_duplicated) +
                          " knot(s) duplicated)"});
    if (observer_) observer_(b, change, time);
  }
  // A topology change recaptures the tearing terms: links still past their limit are recorded
  // again, and handled (or skipped) at the next call.
  seen_ = tear_count(world.terms());
}

}  // namespace viscera::sim
