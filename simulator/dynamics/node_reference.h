#pragma once
/// A node of a body named so that it survives topology changes: a cut renumbers a body's nodes
/// but keeps the rest position of every node it does not create (cutting/hybrid_cut.h), so a
/// tool that holds nodes — a grasper's jaws, a clip, coagulated tissue — finds them again by
/// their rest positions.

#include <span>
#include <vector>

#include "simulator/dynamics/simulation_state.h"

namespace viscera::sim {

struct NodeReference {
  int body = 0;
  int node = 0;              ///< body-local index in the current topology
  Vec3 rest = Vec3::Zero();  ///< m, rest position when taken

  /// Global index into the state's arrays.
  int global(const SimulationState& state) const { return state.body(body).first + node; }
};

/// A reference to body-local node `node` of `body`, with its rest position.
NodeReference reference_node(const SimulationState& state, int body, int node);

/// After a topology change of `body`: every reference to it moves to the node whose rest
/// position is nearest to its own (ties: the lowest index, so the result is deterministic);
/// references whose nearest node lies further than `tolerance` m are dropped. References to
/// other bodies are kept as they are (their global index follows the body's range).
void refind_nodes(const SimulationState& state, int body, std::vector<NodeReference>& nodes,
                  double tolerance = 1e-3);

}  // namespace viscera::sim
