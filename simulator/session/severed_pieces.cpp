#include "simulator/session/severed_pieces.h"

#include <algorithm>

#include "simulator/cutting/fragments.h"
#include "simulator/dynamics/attachment_term.h"
#include "simulator/dynamics/connection_spring_term.h"

namespace viscera::sim {

std::vector<std::uint8_t> held_nodes(const World& world, int body) {
  const auto inverse = world.state().range(world.state().inverse_masses, body);
  std::vector<std::uint8_t> held(inverse.size(), 0);
  for (std::size_t i = 0; i < inverse.size(); ++i)
    held[i] = inverse[i] == 0.0 ? 1 : 0;
  const auto hold = [&](int node) {
    if (node >= 0 && static_cast<std::size_t>(node) < held.size())
      held[static_cast<std::size_t>(node)] = 1;
  };
  for (const auto& term : world.terms()) {
    if (const auto* attachments = dynamic_cast<const AttachmentTerm*>(term.get())) {
      for (const Attachment& a : attachments->attachments())
        if (a.body == body && a.host != body) hold(a.node);
    } else if (const auto* springs = dynamic_cast<const ConnectionSpringTerm*>(term.get())) {
      for (const ConnectionSpring& s : springs->springs()) {
        if (s.body_a == body && s.body_b != body) hold(s.node_a);
        if (s.body_b == body && s.body_a != body) hold(s.node_b);
      }
    }
  }
  return held;
}

std::vector<std::uint8_t> severed_nodes(const core::TetMesh& mesh,
                                        const std::vector<std::uint8_t>& held) {
  const auto fragments = cutting::body_fragments(mesh, held);
  const bool any_held =
      std::any_of(fragments.begin(), fragments.end(), [](const auto& f) { return f.anchored; });
  std::size_t largest = 0;
  for (std::size_t f = 1; f < fragments.size(); ++f)
    if (fragments[f].rest_volume > fragments[largest].rest_volume) largest = f;
  std::vector<std::uint8_t> severed(mesh.nodes.size(), 0);
  for (std::size_t f = 0; f < fragments.size(); ++f) {
    if (fragments[f].anchored || (!any_held && f == largest)) continue;
    for (const int n : fragments[f].nodes)
      severed[static_cast<std::size_t>(n)] = 1;
  }
  return severed;
}

}  // namespace viscera::sim
