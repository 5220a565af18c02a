#pragma once
/// Vessel trees drawn as spline pipes, as in KisMo (seed 001 §5.1.1: "The arterial and venous
/// vessel tree is modeled with KisMo using spline curves for interconnected pipes"): each branch
/// is a Catmull-Rom curve through control points, attached to its parent branch at a fraction of
/// the parent's length.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/curves/catmull_rom.h"
#include "core/scenario/scenario_parts.h"

namespace viscera::templates {

/// One branch. Positions in m.
struct SplineVesselBranch {
  std::vector<core::Vec3> control_points;  ///< at least two
  int parent_branch = -1;                  ///< earlier branch it leaves from, -1 for the root
  double attach = 1.0;                     ///< where on the parent, as a fraction of its length
  double flow_weight = 1.0;                ///< share of flow of this branch's terminal end
};

/// How the branches become segments.
struct SplineVesselOptions {
  double sample_spacing = 2e-3;                              ///< m between samples along each curve
  core::KnotSpacing knots = core::KnotSpacing::Centripetal;  ///< no cusps or self-loops
  double root_radius = 1.5e-3;                               ///< m
  double total_flow = 2.5e-6;                                ///< m³/s
  std::string tree_id = "spline-tree";
  std::string host_object;
};

/// Samples every branch (a child's first point is moved onto its parent at `attach`, where the
/// parent gets a node), links the segments, and gives flows and Murray radii
/// (assign_murray_flows_and_radii): each branch end without children drains flow ∝ flow_weight.
/// Throws core::UsageError naming the branch for fewer than two points, a parent that is not
/// earlier, or attach outside [0, 1].
core::VesselTree spline_vessel_tree(const std::vector<SplineVesselBranch>& branches,
                                    const SplineVesselOptions& options);

/// Branches from JSON: {"branches": [{"points": [[x,y,z], …], "parent": -1, "attach": 1,
/// "flow_weight": 1}, …]} in m. Throws core::ValidationError with the JSON pointer.
std::vector<SplineVesselBranch> spline_branches_from_json(const nlohmann::json& json);

/// Points on the Catmull-Rom curve through `points` (core::CatmullRomSpline, open), about
/// `spacing` m apart, every control point included. Throws core::UsageError for fewer than two
/// points or two equal neighbours.
std::vector<core::Vec3> sample_catmull_rom(const std::vector<core::Vec3>& points, double spacing,
                                           core::KnotSpacing knots);

}  // namespace viscera::templates
