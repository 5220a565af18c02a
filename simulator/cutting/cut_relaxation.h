#pragma once
/// Local mesh enhancement after a cut (seed 000 §5.1): "a set of nodes in the neighborhood of a
/// cut is selected for adjustment. … only interior nodes are free to move in all directions.
/// Nodes on the cut surface can translate only along the surface, while those on the original
/// surface or surfaces resulting from an earlier cut are fixed. All edges incident to a node
/// are considered as springs whose rest lengths equal the average length of those edges. All
/// nodes are considered as mass points with equal masses. … forces resulting from the
/// Lennard-Jones potential … The movement of a node is governed by Newton's equation of motion.
/// … the system is highly damped. … only a few iteration steps."
///
/// Our reading (the paper gives no formula): the Lennard-Jones force along each incident edge,
/// F(r) = 12 ε/r [(r0/r)^12 − (r0/r)^6] with its minimum at r0 = the node's mean incident edge
/// length (σ = 2^(−1/6) r0), unit masses, damped explicit steps v ← c·v + η·F, x ← x + v.
/// A step is kept only when no tet of the node's star inverts and the star's smallest dihedral
/// angle does not decrease, in the deformed and in the rest configuration, so the relaxation
/// never makes the mesh worse. It runs on the still-conforming mesh before node separation, so
/// every moving node is interior to the body and the total volume is unchanged.

#include <vector>

#include "core/math_types.h"
#include "simulator/cutting/topology_change.h"

namespace viscera::sim::cutting {

struct RelaxationOptions {
  int iterations = 3;               ///< "a few iteration steps"
  double damping = 0.3;             ///< velocity kept per step (heavily damped: ≪ 1)
  double max_step_fraction = 0.15;  ///< largest move per step, fraction of r0
  /// Nodes of new tets whose smallest dihedral angle is below this (degrees) are relaxed.
  double relax_below_degrees = 10.0;
};

/// The mesh being relaxed, all arrays indexed by node; star_offset/star_tets: node → tets (CSR).
struct RelaxationMesh {
  const std::vector<core::Tetrahedron>* tets = nullptr;
  std::vector<core::Vec3>* current = nullptr;
  std::vector<core::Vec3>* rest = nullptr;
  const std::vector<int>* star_offset = nullptr;
  const std::vector<int>* star_tets = nullptr;
  /// Per node: its sources (empty = itself with weight 1), updated for moved nodes.
  std::vector<std::vector<NodeSource>>* origin = nullptr;
};

/// One node to relax: free (slide_normal zero) or sliding in the plane normal to slide_normal.
struct RelaxedNode {
  int node = 0;
  core::Vec3 slide_normal = core::Vec3::Zero();
};

/// Relaxes `nodes` in the given order (Gauss–Seidel); returns how many moved.
int relax_cut_neighbourhood(const RelaxationMesh& mesh, const std::vector<RelaxedNode>& nodes,
                            const RelaxationOptions& options);

}  // namespace viscera::sim::cutting
