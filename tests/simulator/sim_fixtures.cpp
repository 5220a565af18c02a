#include "tests/simulator/sim_fixtures.h"

namespace viscera::testing {

core::TetMesh tet_block(int nx, int ny, int nz, double cell) {
  core::TetMesh mesh;
  const auto index = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) mesh.nodes.emplace_back(cell * i, cell * j, cell * k);
  // Kuhn subdivision: the 6 tets along the main diagonal 0 → 7 of each cube.
  static constexpr int kPaths[6][2] = {{1, 3}, {1, 5}, {2, 3}, {2, 6}, {4, 5}, {4, 6}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const auto corner = [&](int c) { return index(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1)); };
        for (const auto& path : kPaths) mesh.tets.push_back({corner(0), corner(path[0]), corner(path[1]), corner(7)});
      }
  core::orient_tets_positively(mesh);
  mesh.surface_faces = core::boundary_faces(mesh.tets);
  return mesh;
}

void jiggle(std::vector<core::Vec3>& nodes, double amplitude, std::uint64_t seed) {
  core::Rng rng(seed);
  for (auto& n : nodes) n += core::Vec3(rng.uniform(-amplitude, amplitude), rng.uniform(-amplitude, amplitude),
                                        rng.uniform(-amplitude, amplitude));
}

}  // namespace viscera::testing
