#pragma once
// Invariants every cut must keep, shared by the cutting tests: positive tets, no dihedral angle
// below the bound, volume kept, surface = boundary of the tets, every fragment closed and
// manifold, and node sources that reproduce the new positions from the old ones.

#include <vector>

#include "core/mesh/tet_mesh.h"
#include "simulator/cutting/topology_change.h"

namespace viscera::testing {

/// A gmsh ball of `radius` m (icosphere of `subdivisions` meshed with its own edge length),
/// built once per (radius, subdivisions) and cached.
const core::TetMesh& cutting_ball(double radius = 0.02, int subdivisions = 3);

/// Smallest dihedral angle over all tets of `mesh` for positions x, degrees.
double smallest_dihedral(const std::vector<core::Tetrahedron>& tets,
                         const std::vector<core::Vec3>& x);

/// Checks the invariants with gtest EXPECTs; `min_dihedral` in degrees.
void expect_valid_cut(const core::TetMesh& before, const std::vector<core::Vec3>& current_before,
                      const sim::cutting::TopologyChange& change, double min_dihedral = 1.0);

}  // namespace viscera::testing
