// The laparoscopic tools on links (issue 17 §4, seed 003 §V): a cell-agent tissue is grasped
// and cut by removing the neighbour links the blades cross, and the grasper's pull is measured
// by the strain of the links at the knots it holds. A LaparoscopicTools part kept apart from
// the tools' mesh cuts in laparoscopic_tools.cpp.
#include <chrono>

#include "simulator/dynamics/agent_tissue_term.h"
#include "simulator/dynamics/kismo_spring_term.h"
#include "simulator/session/laparoscopic_tools.h"

namespace viscera::sim {
namespace {

/// Connected components of the cells of `agents` over its links (a cell without links is one).
int linked_pieces(const AgentTissueTerm& agents, std::size_t cells) {
  std::vector<int> parent(cells);
  for (std::size_t i = 0; i < cells; ++i)
    parent[i] = static_cast<int>(i);
  const auto root = [&](int i) {
    while (parent[static_cast<std::size_t>(i)] != i)
      i = parent[static_cast<std::size_t>(i)] =
          parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
    return i;
  };
  int pieces = static_cast<int>(cells);
  for (const CellConnection& c : agents.connections()) {
    const int a = root(c.a), b = root(c.b);
    if (a != b) parent[static_cast<std::size_t>(a)] = b, --pieces;
  }
  return pieces;
}

}  // namespace

AgentTissueTerm* LaparoscopicTools::agents_of(int body) const {
  for (AgentTissueTerm* agents : agents_)
    if (agents->model().body == body) return agents;
  return nullptr;
}

bool LaparoscopicTools::cut_links(AgentTissueTerm& agents,
                                  std::span<const std::array<core::Vec3, 3>> triangles,
                                  const char* tool, World& world, double time,
                                  LaparoscopySummary& summary, std::vector<SessionEvent>& events) {
  const int body = agents.model().body;
  TissueCut record;
  record.time = time;
  record.tool = tool;
  record.body = agents.model().name;
  const auto cells = world.state().range(world.state().positions, body);
  record.pieces_before = linked_pieces(agents, cells.size());
  const auto start = std::chrono::steady_clock::now();
  int removed = 0;
  for (const auto& t : triangles) {
    removed += agents.cut(world.state(), t[0], t[1], t[2]);
    record.position += (t[0] + t[1] + t[2]) / (3.0 * static_cast<double>(triangles.size()));
  }
  if (removed == 0) return false;
  world.stiffness_changed(body);
  record.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  record.links_removed = removed;
  record.pieces_after = linked_pieces(agents, cells.size());
  summary.cuts.push_back(record);
  events.push_back({time, std::string(tool) + "-cut",
                    "the " + std::string(tool) + " cut " + std::to_string(removed) +
                        " link(s) between the cells of " + record.body +
                        (record.separated() ? ", dividing it" : "")});
  return true;
}

double LaparoscopicTools::grasp_stretch(const World& world) const {
  double largest = 0.0;
  for (const Port& port : ports_)
    if (port.grasp->holding()) largest = std::max(largest, grasp_stretch(world, *port.grasp));
  return largest;
}

double LaparoscopicTools::grasp_stretch(const World& world, const GraspTerm& grasp) const {
  // A grasper holds knots of one body (tissue_between_jaws): only its links are looked at.
  const SimulationState& s = world.state();
  const int body = grasp.held().front().body;
  const BodyNodes& range = s.body(body);
  std::vector<std::uint8_t> held(static_cast<std::size_t>(range.count), 0);
  for (const NodeReference& r : grasp.held())
    held[static_cast<std::size_t>(r.node)] = 1;
  double largest = 0.0;
  const auto strain = [&](int a, int b, double rest) {  // global nodes of the body
    const auto la = static_cast<std::size_t>(a - range.first);
    const auto lb = static_cast<std::size_t>(b - range.first);
    if (!(rest > 0.0) || (!held[la] && !held[lb])) return;
    const double length =
        (s.positions[static_cast<std::size_t>(b)] - s.positions[static_cast<std::size_t>(a)])
            .norm();
    largest = std::max(largest, length / rest - 1.0);
  };
  for (const auto& term : world.terms()) {
    if (const auto* agents = dynamic_cast<const AgentTissueTerm*>(term.get())) {
      if (agents->model().body != body) continue;
      for (const CellConnection& c : agents->connections())
        strain(range.first + c.a, range.first + c.b, c.rest_length);
    } else if (const auto* net = dynamic_cast<const KismoSpringTerm*>(term.get())) {
      if (net->model().body != body) continue;
      const CubicSprings& springs = net->springs();
      for (std::size_t k = 0; k < springs.knots.size(); ++k)
        strain(springs.knots[k][0], springs.knots[k][1], springs.rest_length[k]);
    }
  }
  return largest;
}

}  // namespace viscera::sim
