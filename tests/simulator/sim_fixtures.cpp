#include "tests/simulator/sim_fixtures.h"

namespace viscera::testing {

Sheet make_sheet(int n, double half_width) {
  Sheet s;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      s.positions.emplace_back(-half_width + 2.0 * half_width * i / n,
                               -half_width + 2.0 * half_width * j / n, 0.0);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      s.faces.push_back({a, a + 1, a + n + 2});
      s.faces.push_back({a, a + n + 2, a + n + 1});
    }
  return s;
}

std::shared_ptr<sim::BodyModel> one_material_model(const core::TetMesh& mesh,
                                                   const core::Material& material) {
  auto model = std::make_shared<sim::BodyModel>();
  model->name = "body";
  model->mesh = mesh;
  model->surface =
      mesh.surface_faces.empty() ? core::boundary_faces(mesh.tets) : mesh.surface_faces;
  model->materials = {material};
  model->tet_material.assign(mesh.tets.size(), 0);
  return model;
}

TeschnerBody::TeschnerBody(const core::TetMesh& mesh, const core::Material& material)
    : model(one_material_model(mesh, material)) {
  const std::vector<double> mass =
      mesh.node_mass.empty() ? core::lumped_node_masses(mesh, material.density) : mesh.node_mass;
  model->body = state.add_body("body", mesh.nodes, mass, mesh.fixed);
  distance = std::make_unique<sim::TeschnerDistanceTerm>(model, state);
  area = std::make_unique<sim::TeschnerAreaTerm>(model, state);
  volume = std::make_unique<sim::TeschnerVolumeTerm>(model, state);
}

void jiggle(std::vector<core::Vec3>& nodes, double amplitude, std::uint64_t seed) {
  core::Rng rng(seed);
  for (auto& n : nodes)
    n += core::Vec3(rng.uniform(-amplitude, amplitude), rng.uniform(-amplitude, amplitude),
                    rng.uniform(-amplitude, amplitude));
}

}  // namespace viscera::testing
