#include "simulator/session/severed_pieces.h"

#include <algorithm>

namespace viscera::sim {

std::vector<cutting::Fragment> severed_fragments(const core::TetMesh& mesh,
                                                 const std::vector<std::uint8_t>& held,
                                                 bool lost_every_hold) {
  auto fragments = cutting::body_fragments(mesh, held);
  const bool any_held =
      std::any_of(fragments.begin(), fragments.end(), [](const auto& f) { return f.anchored; });
  std::size_t largest = 0;
  for (std::size_t f = 1; f < fragments.size(); ++f)
    if (fragments[f].rest_volume > fragments[largest].rest_volume) largest = f;
  std::vector<cutting::Fragment> severed;
  for (std::size_t f = 0; f < fragments.size(); ++f)
    if (!fragments[f].anchored && (any_held || lost_every_hold || f != largest))
      severed.push_back(std::move(fragments[f]));
  return severed;
}

std::vector<std::uint8_t> severed_nodes(const core::TetMesh& mesh,
                                        const std::vector<std::uint8_t>& held,
                                        bool lost_every_hold) {
  std::vector<std::uint8_t> severed(mesh.nodes.size(), 0);
  for (const cutting::Fragment& piece : severed_fragments(mesh, held, lost_every_hold))
    for (const int n : piece.nodes)
      severed[static_cast<std::size_t>(n)] = 1;
  return severed;
}

}  // namespace viscera::sim
