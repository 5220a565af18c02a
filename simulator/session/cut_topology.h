#pragma once
/// A cut's new topology as the simulation core takes it (World::topology_changed): the cut's
/// node sources become per-node origins that carry masses and velocities.

#include "simulator/cutting/topology_change.h"
#include "simulator/dynamics/body_topology.h"

namespace viscera::sim {

/// The core's topology of a cut body: rest mesh, current positions, at most four origins per
/// node (an unchanged or copied node has one, a node on a cut edge two, a relaxed node the
/// four corners of its old tet; longer lists keep their four heaviest, renormalised) and the
/// parent of every tet.
BodyTopology topology_of_cut(const cutting::TopologyChange& change);

}  // namespace viscera::sim
