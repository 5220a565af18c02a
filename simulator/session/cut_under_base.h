#pragma once
/// A loop drawn under a pathology's base (issue 17 §4–5; seed 000 §5 leaves it open): the
/// surgeon takes a pedunculated polyp off by passing the loop just beneath its base, through the
/// endometrium it grows from. The loop cuts only pathology bodies, never the wall (its cutting
/// needs the perforation rules); what it does cut under the base is the pathology's hold on the
/// wall — the attachments and connection springs of the nodes it passes under.
///
/// Decided where the seed is silent: a held node (World::held_nodes, excluding fixed nodes) is
/// passed under when the swept surface crosses the segment from 0.1 mm above the node to
/// `kUnderBaseDepth` below it, "below" being from the pathology's centre towards the centre of
/// its held nodes (into the wall it grows on). 3 mm: a loop of 2.5 mm radius drawn deeper than
/// that under a base is in the wall, not under the polyp.

#include <cstdint>
#include <vector>

#include "simulator/cutting/cut_surface.h"
#include "simulator/world/world.h"

namespace viscera::sim {

inline constexpr double kUnderBaseDepth = 0.003;  ///< m

/// Per node of body `body`, 1 where the node holds the body to another one and `swept` passes
/// under it.
std::vector<std::uint8_t> nodes_cut_under(const World& world, int body,
                                          const cutting::CutSurface& swept);

/// Releases the holds of the nodes nodes_cut_under() finds (World::topology_changed with the
/// body's own topology and those nodes released); returns how many.
int release_cut_under(World& world, int body, const cutting::CutSurface& swept);

}  // namespace viscera::sim
