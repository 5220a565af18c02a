#pragma once
/// Bodies built by hand for the physics tests.

#include "core/mesh/tet_mesh.h"
#include "core/random.h"
#include "tests/support/tet_block.h"

namespace viscera::testing {

/// A flat square sheet at z = 0 facing +z, 2·half_width m wide, split into n × n squares of two
/// triangles each: a surface for proxy and instrument tests.
struct Sheet {
  std::vector<core::Vec3> positions;
  std::vector<core::Triangle> faces;
};
Sheet make_sheet(int n, double half_width);

/// Moves every node by a random offset of up to `amplitude` m (core::Rng with `seed`).
void jiggle(std::vector<core::Vec3>& nodes, double amplitude, std::uint64_t seed);

}  // namespace viscera::testing
