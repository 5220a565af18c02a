#pragma once
/// Penalty contact between deformable bodies (seed 000 §4): spatial hashing finds the vertices
/// of one body inside the tetrahedra of another, consistent penetration depths turn them into
/// forces k·d·r on the vertex, and the opposite force goes to the nodes of the tetrahedron it
/// is in, by barycentric weights, so the contact conserves momentum.

#include <vector>

#include "simulator/collision/penetration_depth.h"
#include "simulator/collision/spatial_hash.h"
#include "simulator/physics/deformable_body.h"

namespace viscera::sim {

/// What the contacts of one step did.
struct ContactStatistics {
  int colliding_points = 0;       ///< vertices inside another body
  double max_penetration = 0.0;   ///< m
  double total_force = 0.0;       ///< N, sum of the penalty force magnitudes
};

/// Contact handling for a fixed set of bodies; keeps its hash table and adjacency between steps.
class ContactResponse {
 public:
  /// `bodies` must outlive this object and keep their topology. `stiffness` in N/m per point.
  ContactResponse(const std::vector<DeformableBody>& bodies, double stiffness);

  /// Detects contacts between different bodies at their current positions and adds the penalty
  /// forces to the bodies (after compute_forces(), before integrate()).
  ContactStatistics apply(std::vector<DeformableBody>& bodies);

  double stiffness() const { return stiffness_; }

 private:
  double stiffness_;
  SpatialHash hash_;
  std::vector<VertexAdjacency> adjacency_;
};

}  // namespace viscera::sim
