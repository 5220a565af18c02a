#pragma once
/// A node of a body named so that it survives topology changes: a cut renumbers a body's nodes
/// but keeps the rest position of every node it does not create (cutting/hybrid_cut.h), so a
/// tool that holds nodes — a grasper's jaws, a clip, coagulated tissue — finds them again by
/// their rest positions. A cut that separates a node leaves two copies at one rest position
/// (one on each side, and a chip cut off long ago may be centimetres from its twin in the
/// wall): the copy nearest to where the reference last saw its node is the one it holds.

#include <span>
#include <vector>

#include "simulator/dynamics/simulation_state.h"

namespace viscera::sim {

struct NodeReference {
  int body = 0;
  int node = 0;              ///< body-local index in the current topology
  Vec3 rest = Vec3::Zero();  ///< m, rest position when taken
  Vec3 seen = Vec3::Zero();  ///< m, current position when taken or last noted (note_positions)

  /// Global index into the state's arrays.
  int global(const SimulationState& state) const { return state.body(body).first + node; }
};

/// A reference to body-local node `node` of `body`, with its rest and current positions.
NodeReference reference_node(const SimulationState& state, int body, int node);

/// Records where each of `nodes` is now (after a step), for refind_nodes.
void note_positions(const SimulationState& state, std::span<NodeReference> nodes);

/// After a topology change of `body`: every reference to it moves to the node whose rest
/// position is nearest to its own; among nodes at that rest position (within 1 nm: the copies a
/// cut made of one node) to the one whose current position is nearest to where the reference
/// last saw its node; remaining ties go to the lowest index, so the result is deterministic.
/// References whose nearest node lies further than `tolerance` m are dropped. References to
/// other bodies are kept as they are (their global index follows the body's range). Returns,
/// for each reference kept, its index in `nodes` before the call.
std::vector<std::size_t> refind_nodes(const SimulationState& state, int body,
                                      std::vector<NodeReference>& nodes, double tolerance = 1e-3);

}  // namespace viscera::sim
