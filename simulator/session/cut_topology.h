#pragma once
/// A cut's new topology as the simulation core takes it (World::topology_changed): the cut's
/// node sources become per-node origins that carry masses and velocities.

#include <cstdint>
#include <span>

#include "simulator/cutting/topology_change.h"
#include "simulator/dynamics/body_topology.h"

namespace viscera::sim {

/// The core's topology of a cut body: rest mesh, current positions, at most four origins per
/// node (an unchanged or copied node has one, a node on a cut edge two, a relaxed node the
/// four corners of its old tet; longer lists keep their four heaviest, renormalised), the
/// parent of every tet, and as released the nodes of `held` (World::held_nodes before the cut;
/// old nodes keep their index) that lie on the cut in a piece no other held node holds: a loop
/// drawn through a polyp's base nodes takes the polyp off the wall, where the nodes' hold went
/// with the piece that kept their index. Empty `held`: nothing released.
BodyTopology topology_of_cut(const cutting::TopologyChange& change,
                             std::span<const std::uint8_t> held = {});

}  // namespace viscera::sim
