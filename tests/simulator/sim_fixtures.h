#pragma once
/// Bodies built by hand for the physics tests.

#include "core/mesh/tet_mesh.h"
#include "core/random.h"

namespace viscera::testing {

/// A block of nx × ny × nz cubes of `cell` m, each split into 6 positive tets (Kuhn
/// subdivision, conforming across cubes), with boundary faces. Origin at the min corner.
core::TetMesh tet_block(int nx, int ny, int nz, double cell);

/// Moves every node by a random offset of up to `amplitude` m (core::Rng with `seed`).
void jiggle(std::vector<core::Vec3>& nodes, double amplitude, std::uint64_t seed);

}  // namespace viscera::testing
