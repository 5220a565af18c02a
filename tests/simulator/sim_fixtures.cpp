#include "tests/simulator/sim_fixtures.h"

namespace viscera::testing {

Sheet make_sheet(int n, double half_width) {
  Sheet s;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      s.positions.emplace_back(-half_width + 2.0 * half_width * i / n, -half_width + 2.0 * half_width * j / n, 0.0);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      s.faces.push_back({a, a + 1, a + n + 2});
      s.faces.push_back({a, a + n + 2, a + n + 1});
    }
  return s;
}

void jiggle(std::vector<core::Vec3>& nodes, double amplitude, std::uint64_t seed) {
  core::Rng rng(seed);
  for (auto& n : nodes) n += core::Vec3(rng.uniform(-amplitude, amplitude), rng.uniform(-amplitude, amplitude),
                                        rng.uniform(-amplitude, amplitude));
}

}  // namespace viscera::testing
