#pragma once
/// Checks and derived quantities of vessel trees: children, lengths, flows, Murray's law
/// (Murray 1926: r_parent³ = Σ r_child³ at every branching) and non-intersection of segments.

#include <string>
#include <utility>
#include <vector>

#include "core/scenario/scenario_parts.h"

namespace viscera::templates {

/// Children of every segment, in segment order. Throws core::ValidationError (pointer
/// /segments/i/parent) when a parent index is out of range or not earlier than its child.
std::vector<std::vector<int>> segment_children(const core::VesselTree& tree);

/// Length of a segment in m.
double segment_length(const core::VesselSegment& segment);

/// Number of segments without children.
int terminal_count(const core::VesselTree& tree);

/// Total lumen volume Σ π r² l in m³.
double tree_volume(const core::VesselTree& tree);

/// Largest relative deviation |r_p^γ − Σ r_c^γ| / r_p^γ over segments with children
/// (0 for a tree without branchings).
double murray_deviation(const core::VesselTree& tree, double exponent = 3.0);

/// Smallest distance in m between the centre lines of two segments (Ericson 2005, §5.1.9).
double segment_distance(const core::Vec3& p1, const core::Vec3& q1, const core::Vec3& p2,
                        const core::Vec3& q2);

/// Length in m of the tree path strictly between segments a and b: 0 when they share a node
/// (parent–child, siblings), the lengths of the segments in between otherwise, infinity when they
/// belong to different roots.
double tree_gap(const core::VesselTree& tree, int a, int b);

/// Pairs (a < b) of segments whose walls touch although they are not neighbours: centre-line
/// distance < clearance · (r_a + r_b). Segments that share a node, or that are joined by less
/// than 2 (r_a + r_b) of tree (a vessel sampled in short pieces; the wall of a bifurcation,
/// where daughters branching at 30° or more leave the parent's wall), meet by construction and
/// are not counted. Uses a uniform grid, so it scales to thousands of segments.
std::vector<std::pair<int, int>> find_intersections(const core::VesselTree& tree,
                                                    double clearance = 1.0);

/// One problem with a tree, with the JSON pointer of the member inside the tree.
struct VesselTreeIssue {
  std::string json_pointer;
  std::string message;
};

/// Structural and physiological checks: parents precede children, children start where their
/// parent ends, positive finite radii, lengths and flows, flow conservation (parent flow = Σ
/// children's within 1 %), Murray's law within `murray_tolerance`, and no intersecting segments.
std::vector<VesselTreeIssue> validate_vessel_tree(const core::VesselTree& tree,
                                                  double murray_tolerance = 0.01);

/// Gives a tree consistent flows and radii from its topology: every terminal carries
/// total_flow × weight / Σ weights (weights default to 1), flows add up towards the root, and
/// radii follow Murray's law from the root radius: r = root_radius · (Q / Q_root)^(1/3).
/// Throws core::UsageError for non-positive arguments or a weight count that is not the
/// terminal count.
void assign_murray_flows_and_radii(core::VesselTree& tree, double root_radius, double total_flow,
                                   const std::vector<double>& terminal_weights = {});

}  // namespace viscera::templates
