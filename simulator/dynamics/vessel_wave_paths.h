#pragma once
/// Where pulse waves run on a vessel tree and which knots of the host body they push (seed 001
/// §5.1.1): arc lengths along the hierarchy from its root(s), and the wall knots with their
/// force directions, "from the pipe axis to the object knots on the pipe surface". Plain
/// functions of the tree and the host's rest nodes; lengths in m.

#include <span>
#include <vector>

#include "core/math_types.h"
#include "core/scenario/scenario_parts.h"

namespace viscera::sim {

/// Per segment of `tree`, the arc length in m from the top of the hierarchy (a segment with
/// parent −1) to the segment's proximal end, summed over the ancestors' lengths: where a wave
/// started at a root at time 0 reaches the segment. Branches share their parent's arc, so a wave
/// is duplicated at every bifurcation. Throws core::InputError naming the tree and the segment
/// for a parent index out of range or a cycle.
std::vector<double> proximal_arc_lengths(const core::VesselTree& tree);

/// A knot of the host body on a vessel wall.
struct PulseWallKnot {
  int node = 0;                                ///< index into the host's nodes
  int segment = 0;                             ///< index of the segment it belongs to
  double arc = 0.0;                            ///< m along the hierarchy where the wave meets it
  core::Vec3 direction = core::Vec3::UnitX();  ///< unit, from the segment's axis to the knot
};

/// The host knots nearest each segment of `tree`: the node nearest to each point sampled along
/// the segment's axis every `spacing` m (both ends included), so every segment, however short
/// or however coarse the host, has at least one knot. A node nearest to several segments
/// belongs to the one whose axis is closest. Its arc is the proximal arc of its segment plus
/// its projection on the axis (clamped to the segment); its direction points from the axis to
/// it (any direction across the axis when it lies on it). Sorted by arc, then node. Throws
/// core::InputError for an empty host or a non-positive spacing.
std::vector<PulseWallKnot> pulse_wall_knots(const core::VesselTree& tree,
                                            std::span<const core::Vec3> host_nodes, double spacing);

}  // namespace viscera::sim
