// SOFA scenes: the XML parsed with VTK's XML parser, every file it names read back, and the
// material mapping checked against the simulator's own energies.
#include <gtest/gtest.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUtilities.h>

#include <sstream>

#include "core/error.h"
#include "exporters/scenario_exporter.h"
#include "exporters/sofa_material.h"
#include "importers/mesh_reader.h"
#include "tests/exporters/export_fixtures.h"
#include "tests/exporters/sofa_scene_reader.h"
#include "tests/support/tet_block.h"

namespace viscera::exporters {
namespace {

const core::Scenario& scenario() {
  return testing::export_scenario_fixture();
}

vtkXMLDataElement* child(vtkXMLDataElement* parent, const std::string& element,
                         const std::string& name = "") {
  for (int i = 0; i < parent->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* e = parent->GetNestedElement(i);
    if (element == e->GetName() &&
        (name.empty() || (e->GetAttribute("name") != nullptr && name == e->GetAttribute("name"))))
      return e;
  }
  return nullptr;
}

std::vector<int> integers(const char* text) {
  std::istringstream in(text);
  std::vector<int> values;
  for (int v; in >> v;)
    values.push_back(v);
  return values;
}

class SofaExport : public ::testing::Test {
 protected:
  void SetUp() override {
    scene_path_ = testing::export_fixture(ExportFormat::Sofa, "patient.scn");
    root_ = vtkSmartPointer<vtkXMLDataElement>::Take(
        vtkXMLUtilities::ReadElementFromFile(scene_path_.string().c_str()));
    ASSERT_NE(root_, nullptr) << "the scene is not well-formed XML";
  }
  std::filesystem::path file(vtkXMLDataElement* e, const char* attribute = "filename") const {
    return scene_path_.parent_path() / e->GetAttribute(attribute);
  }
  std::filesystem::path scene_path_;
  vtkSmartPointer<vtkXMLDataElement> root_;
};

TEST_F(SofaExport, the_root_has_the_session_step_gravity_and_one_solver) {
  EXPECT_STREQ(root_->GetName(), "Node");
  EXPECT_DOUBLE_EQ(std::stod(root_->GetAttribute("dt")), scenario().session.time_step);
  EXPECT_STREQ(root_->GetAttribute("gravity"), "0 0 -9.81");
  EXPECT_NE(child(root_, "EulerImplicitSolver"), nullptr);
  EXPECT_NE(child(root_, "CGLinearSolver"), nullptr);
}

TEST_F(SofaExport, the_tet_body_loads_its_mesh_fixes_its_base_and_maps_its_textured_surface) {
  vtkXMLDataElement* ball = child(root_, "Node", "ball");
  ASSERT_NE(ball, nullptr);
  const core::SceneObject& source = scenario().objects[0];
  const core::TetMesh body = importers::read_tet_mesh(file(child(ball, "MeshVTKLoader")));
  ASSERT_EQ(body.nodes.size(), source.body.nodes.size());
  EXPECT_EQ(body.tets, source.body.tets);
  for (std::size_t i = 0; i < body.nodes.size(); ++i)
    EXPECT_LT((body.nodes[i] - source.body.nodes[i]).norm(), 1e-12);

  std::vector<int> fixed;
  for (std::size_t i = 0; i < source.body.fixed.size(); ++i) {
    if (source.body.fixed[i] != 0) fixed.push_back(static_cast<int>(i));
  }
  ASSERT_FALSE(fixed.empty());
  EXPECT_EQ(integers(child(ball, "FixedProjectiveConstraint")->GetAttribute("indices")), fixed);

  const SofaElasticity expected = sofa_elasticity(scenario().materials.at(source.material));
  vtkXMLDataElement* fem = child(ball, "TetrahedronFEMForceField");
  ASSERT_NE(fem, nullptr);
  EXPECT_DOUBLE_EQ(std::stod(fem->GetAttribute("youngModulus")), expected.young_modulus);
  EXPECT_DOUBLE_EQ(std::stod(fem->GetAttribute("poissonRatio")), expected.poisson_ratio);
  EXPECT_DOUBLE_EQ(std::stod(child(ball, "DiagonalMass")->GetAttribute("massDensity")),
                   scenario().materials.at(source.material).density);

  vtkXMLDataElement* visual = child(ball, "Node", "visual");
  ASSERT_NE(visual, nullptr);
  const core::SurfaceMesh surface = importers::read_mesh(file(child(visual, "MeshOBJLoader")));
  EXPECT_EQ(surface.triangles.size(), source.surface.triangles.size());
  EXPECT_EQ(
      testing::file_bytes(file(child(visual, "OglModel"), "texturename")),
      testing::export_textures_fixture().at(scenario().textures.at("ball-skin").maps.at("albedo")));
  EXPECT_NE(child(visual, "BarycentricMapping"), nullptr);
}

TEST_F(SofaExport, mass_spring_bodies_use_springs_fixtures_are_visual_only_and_connections_attach) {
  vtkXMLDataElement* twin = child(root_, "Node", "twin");
  ASSERT_NE(twin, nullptr);
  EXPECT_EQ(child(twin, "TetrahedronFEMForceField"), nullptr);
  // The fixture's edges differ in share / length, so no single tetrahedraStiffness fits: the
  // springs are listed one by one with the simulator's constants.
  const testing::SofaSceneReader reader(scene_path_);
  const auto built = reader.body_springs(*reader.body_node("twin"));
  const auto expected = kismo_springs(scenario(), scenario().objects[1]);
  ASSERT_EQ(built.size(), expected.size());
  for (std::size_t i = 0; i < built.size(); ++i) {
    EXPECT_EQ(built[i].a, expected[i].a);
    EXPECT_DOUBLE_EQ(built[i].stiffness, expected[i].stiffness);
    EXPECT_DOUBLE_EQ(built[i].rest_length, expected[i].rest_length);
  }

  vtkXMLDataElement* plate = child(root_, "Node", "plate");
  ASSERT_NE(plate, nullptr);
  EXPECT_EQ(child(plate, "MechanicalObject"), nullptr);
  EXPECT_NE(child(plate, "Node", "visual"), nullptr);

  vtkXMLDataElement* link = child(root_, "SpringForceField", "ball-twin");
  ASSERT_NE(link, nullptr);
  EXPECT_STREQ(link->GetAttribute("object1"), "@ball/dofs");
  std::istringstream spring(link->GetAttribute("spring"));
  std::vector<double> values;
  for (double v; spring >> v;)
    values.push_back(v);
  ASSERT_EQ(values.size(), 10u);  // two springs: i j stiffness damping rest-length
  EXPECT_DOUBLE_EQ(values[2], 250.0);
  EXPECT_NEAR(values[4],
              (scenario().objects[0].body.nodes[0] - scenario().objects[1].body.nodes[0]).norm(),
              1e-15);
  // The twin's attached nodes 0 and 1 hang on their springs: never fixed as well.
  for (const int n : reader.fixed(*reader.body_node("twin")))
    EXPECT_GT(n, 1);
}

TEST(SofaMaterial, one_tetrahedra_stiffness_is_written_only_when_it_fits_every_edge) {
  // MeshSpringForceField gives each edge S / l0: edges with equal k·l0 share one S.
  std::vector<SofaSpring> springs = {{0, 1, 100.0, 0.0, 0.01}, {1, 2, 50.0, 0.0, 0.02}};
  ASSERT_TRUE(uniform_tetrahedra_stiffness(springs, 1e-3).has_value());
  EXPECT_NEAR(*uniform_tetrahedra_stiffness(springs, 1e-3), 1.0, 1e-12);
  springs[1].stiffness = 60.0;
  EXPECT_FALSE(uniform_tetrahedra_stiffness(springs, 1e-3).has_value());
}

TEST(SofaMaterial, a_pure_spring_net_maps_to_the_cauchy_poisson_ratio) {
  core::Material material;
  material.distance_stiffness = 3000.0;
  material.volume_stiffness = 0.0;
  material.distance_damping = 6.0;
  const SofaElasticity e = sofa_elasticity(material);
  EXPECT_NEAR(e.poisson_ratio, 0.25, 1e-15);
  EXPECT_NEAR(e.young_modulus, 3000.0 / 6.0, 1e-9);  // E = 5μ/2 with μ = s_D/15
  EXPECT_NEAR(e.rayleigh_stiffness, 0.002, 1e-15);
  material.volume_stiffness = 1e9;
  EXPECT_DOUBLE_EQ(sofa_elasticity(material).poisson_ratio, kMaxPoissonRatio);
  material.distance_stiffness = 0.0;
  EXPECT_THROW(sofa_elasticity(material), core::InputError);
}

/// Teschner distance and volume energies (seed 000 eq. 4 and 6, the simulator's constants) of
/// a block whose nodes are moved by x → F x.
double teschner_energy(const core::TetMesh& rest, const core::Mat3& deformation,
                       const core::Material& material) {
  std::map<std::array<int, 2>, double> share;
  double energy = 0.0;
  for (std::size_t t = 0; t < rest.tets.size(); ++t) {
    const auto& tet = rest.tets[t];
    const double v0 = core::signed_volume(rest, static_cast<int>(t));
    const auto p = [&](int i) {
      return core::Vec3(deformation * rest.nodes[static_cast<std::size_t>(tet[i])]);
    };
    const double c = (core::signed_volume(p(0), p(1), p(2), p(3)) - v0) / v0;
    energy += 0.5 * material.volume_stiffness * v0 * c * c;
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b)
        share[{std::min(tet[a], tet[b]), std::max(tet[a], tet[b])}] += v0 / 6.0;
    }
  }
  for (const auto& [edge, s] : share) {
    const core::Vec3 d = rest.nodes[static_cast<std::size_t>(edge[1])] -
                         rest.nodes[static_cast<std::size_t>(edge[0])];
    const double c = ((deformation * d).norm() - d.norm()) / d.norm();
    energy += 0.5 * material.distance_stiffness * s * c * c;
  }
  return energy;
}

TEST(SofaMaterial, under_uniform_dilation_the_mapped_elastic_energy_equals_the_simulators_energy) {
  // Dilation strains every edge equally whatever its direction, so the isotropic average of the
  // mapping is exact here: W = (3λ/2 · 3 + 3μ) e² = ½ s_D e² + ½ s_V (3e)² at small e.
  const core::TetMesh block = testing::tet_block(3, 3, 3, 0.01);
  core::Material material;
  material.distance_stiffness = 4000.0;
  material.volume_stiffness = 1500.0;
  const double e = 1e-5;
  const double simulated = teschner_energy(block, (1.0 + e) * core::Mat3::Identity(), material);
  const SofaElasticity mapped = sofa_elasticity(material);
  const double mu = mapped.young_modulus / (2.0 * (1.0 + mapped.poisson_ratio));
  const double lambda = mapped.young_modulus * mapped.poisson_ratio /
                        ((1.0 + mapped.poisson_ratio) * (1.0 - 2.0 * mapped.poisson_ratio));
  const double elastic =
      core::total_volume(block) * (mu * 3.0 * e * e + 0.5 * lambda * 9.0 * e * e);
  EXPECT_NEAR(simulated, elastic, 1e-4 * elastic);
}

}  // namespace
}  // namespace viscera::exporters
