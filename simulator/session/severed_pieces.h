#pragma once
/// Which pieces of a cut body are still held by the patient, and which were cut off: what the
/// loop's chips are, and what no longer bleeds (a severed piece has no blood supply).

#include <cstdint>
#include <vector>

#include "core/mesh/tet_mesh.h"
#include "simulator/world/world.h"

namespace viscera::sim {

/// Per node of `body`, 1 for a node that holds it in place: a fixed node, a node attached to
/// another body's tets (a pathology on its wall), or a node of a connection spring to another
/// body.
std::vector<std::uint8_t> held_nodes(const World& world, int body);

/// Per node of `mesh`, 1 for a node of a piece (a connected component) with no held node. A
/// body held nowhere keeps its largest piece (by rest volume) as the patient's.
std::vector<std::uint8_t> severed_nodes(const core::TetMesh& mesh,
                                        const std::vector<std::uint8_t>& held);

}  // namespace viscera::sim
