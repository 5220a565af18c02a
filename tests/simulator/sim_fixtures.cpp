#include "tests/simulator/sim_fixtures.h"

namespace viscera::testing {

void jiggle(std::vector<core::Vec3>& nodes, double amplitude, std::uint64_t seed) {
  core::Rng rng(seed);
  for (auto& n : nodes) n += core::Vec3(rng.uniform(-amplitude, amplitude), rng.uniform(-amplitude, amplitude),
                                        rng.uniform(-amplitude, amplitude));
}

}  // namespace viscera::testing
