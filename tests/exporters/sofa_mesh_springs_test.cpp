// A KisMo body whose edges all carry the same k·l0 is written as one MeshSpringForceField:
// SOFA builds S / l0 per edge (MeshSpringForceField.inl), which must be Viscera's constant.
#include <gtest/gtest.h>

#include "exporters/scenario_exporter.h"
#include "exporters/sofa_material.h"
#include "tests/exporters/sofa_scene_reader.h"
#include "tests/support/test_paths.h"

namespace viscera::exporters {
namespace {

/// One regular tetrahedron (edge 2√2 cm) as a mass-spring body hanging from one fixed node.
core::Scenario regular_tet_scenario() {
  core::Scenario scenario;
  scenario.metadata.name = "regular tet";
  core::Material material;
  material.id = "net";
  material.distance_stiffness = 12000.0;
  material.distance_damping = 3.0;
  scenario.materials[material.id] = material;
  core::SceneObject tet;
  tet.id = "tet";
  tet.material = material.id;
  tet.body_kind = core::BodyKind::MassSpring;
  tet.body.nodes = {core::Vec3(0.01, 0.01, 0.01), core::Vec3(0.01, -0.01, -0.01),
                    core::Vec3(-0.01, 0.01, -0.01), core::Vec3(-0.01, -0.01, 0.01)};
  tet.body.tets = {{0, 1, 2, 3}};
  core::orient_tets_positively(tet.body);
  tet.body.surface_faces = core::boundary_faces(tet.body.tets);
  tet.body.node_mass = core::lumped_node_masses(tet.body, material.density);
  tet.body.fixed = {1, 0, 0, 0};
  tet.surface.vertices = tet.body.nodes;
  tet.surface.triangles = tet.body.surface_faces;
  scenario.objects.push_back(tet);
  return scenario;
}

TEST(SofaMeshSprings, one_tetrahedra_stiffness_gives_every_edge_visceras_constant) {
  const core::Scenario scenario = regular_tet_scenario();
  const std::filesystem::path scene = testing::scratch_dir() / "tet.scn";
  export_scenario(scenario, ExportFormat::Sofa, scene);
  const testing::SofaSceneReader reader(scene);
  const testing::SofaElement* node = reader.body_node("tet");
  ASSERT_NE(node, nullptr);
  const testing::SofaElement* springs = node->child("MeshSpringForceField");
  ASSERT_NE(springs, nullptr);
  EXPECT_TRUE(springs->has("tetrahedraStiffness"));
  EXPECT_FALSE(springs->has("tetrasStiffness")) << "the legacy alias";
  const auto built = reader.body_springs(*node);
  const auto expected = kismo_springs(scenario, scenario.objects[0]);
  ASSERT_EQ(built.size(), 6u);
  ASSERT_EQ(expected.size(), 6u);
  for (std::size_t i = 0; i < built.size(); ++i) {
    EXPECT_NEAR(built[i].stiffness, expected[i].stiffness, 1e-9 * expected[i].stiffness);
    EXPECT_DOUBLE_EQ(built[i].damping, 0.0) << "damping is the solver's Rayleigh β";
  }
  // k_e = s_D · (V/6) / l0² for the one tet: 12000 Pa · V/6 / (8e-4 m²).
  const double volume = core::total_volume(scenario.objects[0].body);
  EXPECT_NEAR(built[0].stiffness, 12000.0 * volume / 6.0 / 8e-4, 1e-9);
  const double beta =
      std::stod(reader.root().child("EulerImplicitSolver")->attribute("rayleighStiffness"));
  EXPECT_DOUBLE_EQ(beta, 3.0 / 12000.0);
}

}  // namespace
}  // namespace viscera::exporters
