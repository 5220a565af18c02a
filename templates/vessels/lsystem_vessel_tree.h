#pragma once
/// Vessel trees from L-systems (seed 001 §3.3: "L-Systems are well known to produce tree-like
/// structures"): the spatial turtle draws centre lines, the grammar's widths set how flow splits,
/// and radii then follow Murray's law so the tree is physiologically consistent.

#include <string>

#include "core/lsystem/lsystem.h"
#include "core/lsystem/turtle.h"
#include "core/scenario/scenario_parts.h"
#include "templates/vessels/perfusion_domain.h"

namespace viscera::templates {

/// A spatial branching grammar for arterial trees: dichotomous, asymmetric (the daughters' width
/// ratios 0.79 and 0.72 split flow about 57:43 by Murray's law), rolling 90–137° between
/// generations so branches fill space. Lengths in units of the turtle step.
inline constexpr const char* kDefaultVesselGrammar =
    "axiom: A(1,1)\n"
    "A(l,w) : l > 0.15 -> F(l,w)[&(32)/(90)A(l*0.78,w*0.79)][^(28)\\(90)A(l*0.72,w*0.72)] : 0.5\n"
    "A(l,w) : l > 0.15 -> F(l,w)[^(30)/(137)A(l*0.78,w*0.79)][&(34)A(l*0.72,w*0.72)] : 0.5\n";

/// What to draw and how to scale it. Grammar lengths (F parameters) are in units of
/// turtle.step, which is in m; turtle.origin is in m.
struct LsystemVesselOptions {
  int generations = 6;
  std::uint64_t seed = 1;                   ///< stochastic productions
  core::TurtleOptions turtle;               ///< origin, heading, step (m), angle, jitter, …
  double root_radius = 1.5e-3;              ///< m
  double total_flow = 2.5e-6;               ///< m³/s
  const PerfusionDomain* domain = nullptr;  ///< when set, branches leaving it are cut off
  bool prune_intersections = true;  ///< cut off later branches whose walls touch earlier ones
  std::string tree_id = "lsystem-tree";
  std::string host_object;
};

/// Derives the grammar, draws it with the spatial turtle and converts the strokes to segments
/// (parents first). Terminal flows are proportional to the cube of the stroke width at the
/// terminal, so a grammar that narrows one branch more than another sends it less blood; every
/// radius then follows r = root_radius·(Q/Q_root)^(1/3). A stroke that does not start where its
/// parent ends (after an `f` move) starts a new root. With prune_intersections, a branch whose
/// wall touches an earlier segment it shares no node with is cut off with everything below it,
/// and flows and radii are recomputed, until no walls touch. Throws core::InputError when
/// nothing is drawn inside the domain.
core::VesselTree lsystem_vessel_tree(const core::Lsystem& grammar,
                                     const LsystemVesselOptions& options);

}  // namespace viscera::templates
