#include "tests/exporters/sofa_template_cases.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include "tests/exporters/export_fixtures.h"
#include "tests/support/command_runner.h"

namespace viscera::testing {

namespace fs = std::filesystem;

/// The package of a case made by `viscera new`, once per build of the program for all the
/// test processes.
fs::path template_package(const TemplateCase& c) {
  const auto built = fs::last_write_time(fs::path(VISCERA_BINARY_DIR) / "bin" / "viscera");
  const fs::path shared =
      shared_test_folder() / ("sofa-" + std::string(c.label) + "-" +
                              std::to_string(built.time_since_epoch().count()) + ".vscene");
  if (!fs::exists(shared)) {
    const fs::path work = shared_test_folder() / (".sofa-" + std::to_string(::getpid()) + c.label);
    fs::create_directories(work);
    const fs::path made = work / "p.vscene";
    const auto result = run_program("viscera",
                                    std::string("new --template ") + c.template_name + " --seed 2" +
                                        c.sets + " -o " + shell_quote(made.string()),
                                    work);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    std::error_code taken;  // another test process may have put its copy in place first
    fs::rename(made, shared, taken);
    fs::remove_all(work);
  }
  return shared;
}

const core::Material& material_of_tet(const core::Scenario& s, const core::SceneObject& o,
                                      std::size_t t) {
  std::string id = o.material;
  if (t < o.body.tet_labels.size() && o.layer_materials.contains(o.body.tet_labels[t]))
    id = o.layer_materials.at(o.body.tet_labels[t]);
  return s.materials.at(id);
}

/// Viscera's KisMo edge constants (simulator/physics/deformable_body.h): k1 = c₁ · share / l0 on
/// the strain, i.e. c₁ share / l0² in N/m, and damping s_d share / l0² in N·s/m.
std::map<std::pair<int, int>, std::pair<double, double>> viscera_edges(const core::Scenario& s,
                                                                       const core::SceneObject& o) {
  std::map<std::pair<int, int>, std::pair<double, double>> edges;
  for (std::size_t t = 0; t < o.body.tets.size(); ++t) {
    const core::Material& m = material_of_tet(s, o, t);
    const double c1 = m.stress_strain && m.stress_strain->cubic.size() == 4
                          ? m.stress_strain->cubic[1]
                          : m.distance_stiffness;
    const double share = core::signed_volume(o.body, static_cast<int>(t)) / 6.0;
    const auto& tet = o.body.tets[t];
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b) {
        auto& e = edges[{std::min(tet[a], tet[b]), std::max(tet[a], tet[b])}];
        e.first += c1 * share;
        e.second += m.distance_damping * share;
      }
    }
  }
  for (auto& [edge, k] : edges) {
    const double l2 = (o.body.nodes[static_cast<std::size_t>(edge.second)] -
                       o.body.nodes[static_cast<std::size_t>(edge.first)])
                          .squaredNorm();
    k.first /= l2;
    k.second /= l2;
  }
  return edges;
}

/// The plugin of each component type, from the SOFA v26.06 source tree (Sofa/Component/...).
std::string plugin_of(const std::string& type) {
  static const std::map<std::string, std::string> table = {
      {"MeshVTKLoader", "Sofa.Component.IO.Mesh"},
      {"MeshOBJLoader", "Sofa.Component.IO.Mesh"},
      {"MeshTopology", "Sofa.Component.Topology.Container.Constant"},
      {"MechanicalObject", "Sofa.Component.StateContainer"},
      {"DiagonalMass", "Sofa.Component.Mass"},
      {"TetrahedronFEMForceField", "Sofa.Component.SolidMechanics.FEM.Elastic"},
      {"MeshSpringForceField", "Sofa.Component.SolidMechanics.Spring"},
      {"SpringForceField", "Sofa.Component.SolidMechanics.Spring"},
      {"FixedProjectiveConstraint", "Sofa.Component.Constraint.Projective"},
      {"EulerImplicitSolver", "Sofa.Component.ODESolver.Backward"},
      {"CGLinearSolver", "Sofa.Component.LinearSolver.Iterative"},
      {"BarycentricMapping", "Sofa.Component.Mapping.Linear"},
      {"SubsetMapping", "Sofa.Component.Mapping.Linear"},
      {"OglModel", "Sofa.GL.Component.Rendering3D"},
      {"CollisionPipeline", "Sofa.Component.Collision.Detection.Algorithm"},
      {"BruteForceBroadPhase", "Sofa.Component.Collision.Detection.Algorithm"},
      {"BVHNarrowPhase", "Sofa.Component.Collision.Detection.Algorithm"},
      {"MinProximityIntersection", "Sofa.Component.Collision.Detection.Intersection"},
      {"LocalMinDistance", "Sofa.Component.Collision.Detection.Intersection"},
      {"CollisionResponse", "Sofa.Component.Collision.Response.Contact"},
      {"TriangleCollisionModel", "Sofa.Component.Collision.Geometry"},
      {"LineCollisionModel", "Sofa.Component.Collision.Geometry"},
      {"PointCollisionModel", "Sofa.Component.Collision.Geometry"},
      {"DefaultAnimationLoop", ""},  // Sofa.Simulation.Core
      {"RequiredPlugin", ""},
  };
  return table.at(type);
}

}  // namespace viscera::testing
