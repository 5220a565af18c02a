#pragma once
/// Bodies built by hand for the physics tests.

#include "core/mesh/tet_mesh.h"
#include "core/random.h"
#include "tests/support/tet_block.h"

namespace viscera::testing {

/// Moves every node by a random offset of up to `amplitude` m (core::Rng with `seed`).
void jiggle(std::vector<core::Vec3>& nodes, double amplitude, std::uint64_t seed);

}  // namespace viscera::testing
