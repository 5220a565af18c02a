#pragma once
/// Which pieces of a cut body are still held by the patient, and which were cut off: what the
/// loop's chips are, and what no longer bleeds (a severed piece has no blood supply).

#include <cstdint>
#include <vector>

#include "core/mesh/tet_mesh.h"
#include "simulator/cutting/fragments.h"

namespace viscera::sim {

/// The pieces (connected components, in cutting::body_fragments order) of `mesh` with no node
/// flagged in `held` (World::held_nodes). A body held nowhere keeps its largest piece (by rest
/// volume) as the patient's — unless `lost_every_hold`: the body was held and every hold it had
/// was cut (a loop drawn under a polyp's base, cut_under_base.h), so every piece is cut off.
std::vector<cutting::Fragment> severed_fragments(const core::TetMesh& mesh,
                                                 const std::vector<std::uint8_t>& held,
                                                 bool lost_every_hold = false);

/// Per node of `mesh`, 1 for a node of a severed piece (severed_fragments).
std::vector<std::uint8_t> severed_nodes(const core::TetMesh& mesh,
                                        const std::vector<std::uint8_t>& held,
                                        bool lost_every_hold = false);

}  // namespace viscera::sim
