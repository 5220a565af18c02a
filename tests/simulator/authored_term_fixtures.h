#pragma once
// Bodies in a SimulationState built by hand, for the tests of the authored-behaviour terms
// (plasticity, tearing, motility, pulse waves, cell agents).

#include <memory>
#include <vector>

#include "core/mesh/tet_mesh.h"
#include "simulator/dynamics/body_model.h"
#include "simulator/dynamics/force_term.h"
#include "simulator/dynamics/simulation_state.h"
#include "tests/support/tet_block.h"

namespace viscera::testing {

/// Adds `mesh` as a body of `state` with one `material` (lumped masses from its density) and
/// returns its model; nodes with `held(x)` are fixed.
template <class Held>
std::shared_ptr<sim::BodyModel> add_tet_body(sim::SimulationState& state, const std::string& name,
                                             core::TetMesh mesh, const core::Material& material,
                                             Held held) {
  auto model = std::make_shared<sim::BodyModel>();
  model->name = name;
  model->kind = sim::BodyModelKind::Teschner;
  const std::vector<double> mass = core::lumped_node_masses(mesh, material.density);
  std::vector<std::uint8_t> fixed(mesh.nodes.size(), 0);
  for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
    fixed[i] = held(mesh.nodes[i]) ? 1 : 0;
  model->surface = mesh.surface_faces;
  model->materials = {material};
  model->tet_material.assign(mesh.tets.size(), 0);
  model->mesh = std::move(mesh);
  model->body = state.add_body(name, model->mesh.nodes, mass, fixed);
  return model;
}

/// A constant load in N on some nodes (E = −Σ F·x): how a test pulls on a body.
class TestLoad : public sim::ForceTerm {
 public:
  std::string name() const override { return "test-load"; }
  double energy(std::span<const core::Vec3> x) const override {
    double e = 0.0;
    for (std::size_t k = 0; k < nodes.size(); ++k)
      e -= force.dot(x[static_cast<std::size_t>(nodes[k])]);
    return e;
  }
  double add_forces(std::span<const core::Vec3> x, std::span<const core::Vec3>,
                    std::span<core::Vec3> f) const override {
    for (const int n : nodes)
      f[static_cast<std::size_t>(n)] += force;
    return energy(x);
  }
  void declare_blocks(sim::BlockPattern&) const override {}
  void add_stiffness(std::span<const core::Vec3>, double, bool,
                     sim::BlockSparseMatrix&) const override {}

  std::vector<int> nodes;
  core::Vec3 force = core::Vec3::Zero();
};

}  // namespace viscera::testing
