#pragma once
// Structured tet meshes shared by the physics tests and benchmarks.

#include <string>

#include "core/mesh/tet_mesh.h"
#include "core/scenario/scenario.h"

namespace viscera::testing {

/// nx × ny × nz cubes of `cell` m, 6 tets each (Kuhn subdivision), boundary faces included.
inline core::TetMesh tet_block(int nx, int ny, int nz, double cell) {
  core::TetMesh mesh;
  const auto index = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        mesh.nodes.emplace_back(cell * i, cell * j, cell * k);
  static constexpr int kPaths[6][2] = {{1, 3}, {1, 5}, {2, 3}, {2, 6}, {4, 5}, {4, 6}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const auto corner = [&](int c) {
          return index(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
        };
        for (const auto& path : kPaths)
          mesh.tets.push_back({corner(0), corner(path[0]), corner(path[1]), corner(7)});
      }
  core::orient_tets_positively(mesh);
  mesh.surface_faces = core::boundary_faces(mesh.tets);
  return mesh;
}

/// The "soft" tissue of the physics tests (id "soft"): 20 kPa distance and volume stiffness,
/// `damping` Pa·s distance damping, 1000 kg/m³.
inline core::Material soft_test_material(double damping = 50.0) {
  core::Material material;
  material.id = "soft";
  material.density = 1000.0;
  material.distance_stiffness = 20000.0;
  material.volume_stiffness = 20000.0;
  material.distance_damping = damping;
  return material;
}

/// Object `id` of material "soft": tet_block(nx, ny, nz, cell) with its nodes at z = 0 held.
inline core::SceneObject held_block(const std::string& id, int nx, int ny, int nz, double cell) {
  core::SceneObject block;
  block.id = id;
  block.material = "soft";
  block.body_kind = core::BodyKind::TetMesh;
  block.body = tet_block(nx, ny, nz, cell);
  block.body.fixed.assign(block.body.nodes.size(), 0);
  for (std::size_t n = 0; n < block.body.nodes.size(); ++n)
    block.body.fixed[n] = block.body.nodes[n].z() < 1e-9 ? 1 : 0;
  return block;
}

/// A scenario of one 4 × 4 × 2 cm soft block (object "block") with its bottom face held; its
/// top face is at z = 2 cm.
inline core::Scenario held_soft_block() {
  core::Scenario scenario;
  scenario.materials["soft"] = soft_test_material();
  scenario.objects.push_back(held_block("block", 4, 4, 2, 0.01));
  return scenario;
}

}  // namespace viscera::testing
