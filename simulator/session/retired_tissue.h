#pragma once
/// Tissue that leaves the simulation during a session (issue 17 §3): the shreds of a resection
/// too small to be chips, which the distension flow then carries as debris particles.
///
/// A retired fragment's tets and surface faces leave its body's mesh; its nodes stay where they
/// are, without mass (so fixed) and in no tet or face, so that every other node of the body keeps
/// its index — the per-node data of the session's other parts (bleeding sources, chips, traces)
/// stays valid. The world rebuilds the body's terms, contact and solver from the smaller mesh.

#include <span>

#include "simulator/cutting/fragments.h"
#include "simulator/dynamics/body_topology.h"
#include "simulator/world/world.h"

namespace viscera::sim {

/// The topology of body `body` of `world` without `fragments` (connected components of its
/// mesh, cutting::body_fragments), for World::topology_changed.
BodyTopology topology_without(const World& world, int body,
                              std::span<const cutting::Fragment> fragments);

/// The centre of a fragment at the body's current `positions`: its nodes' mean, m.
core::Vec3 fragment_centre(const cutting::Fragment& fragment,
                           std::span<const core::Vec3> positions);

/// The radius of the sphere of `volume` m³, m.
double equivalent_radius(double volume);

}  // namespace viscera::sim
