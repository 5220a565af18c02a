#include "tests/simulator/session_fixtures.h"

#include "core/json_eigen.h"
#include "core/mesh/surface_embedding.h"
#include "core/meshing/tet_mesher.h"
#include "core/primitives/icosphere.h"

namespace viscera::testing {
namespace {

using core::Vec3;

core::TaskSpec task(const std::string& id, const std::string& kind, nlohmann::json parameters) {
  return {id, id, kind, std::move(parameters)};
}

core::Scenario build_cavity() {
  core::Scenario scenario;
  scenario.metadata.name = "cavity";
  scenario.procedure = "hysteroscopy";
  core::Material wall;
  wall.id = "wall";
  wall.distance_stiffness = 20000.0;
  wall.volume_stiffness = 20000.0;
  wall.distance_damping = 50.0;
  scenario.materials[wall.id] = wall;
  const core::SurfaceMesh outer = core::make_icosphere(kCavityRadius + kWallThickness, 2);
  const core::SurfaceMesh inner = core::make_icosphere(kCavityRadius, 3);
  core::TetMeshingOptions meshing;
  meshing.cell_size = 0.006;
  core::SceneObject uterus;
  uterus.id = "uterus";
  uterus.material = "wall";
  uterus.body_kind = core::BodyKind::TetMesh;
  uterus.body = core::mesh_region_between(outer, {inner}, meshing);
  uterus.body.fixed.assign(uterus.body.nodes.size(), 0);
  for (std::size_t n = 0; n < outer.vertices.size(); ++n)
    uterus.body.fixed[n] = 1;
  // The visual surface is the body's boundary (outer, then the cavity wall facing inwards).
  const std::size_t surface_nodes = outer.vertices.size() + inner.vertices.size();
  uterus.surface.vertices.assign(uterus.body.nodes.begin(),
                                 uterus.body.nodes.begin() + static_cast<long>(surface_nodes));
  uterus.surface.triangles = uterus.body.surface_faces;
  std::vector<double> cavity(surface_nodes, 0.0);
  for (std::size_t n = outer.vertices.size(); n < surface_nodes; ++n)
    cavity[n] = 1.0;
  uterus.surface.vertex_attributes["cavity"] = cavity;
  uterus.embedding = core::embed_points(uterus.surface.vertices, uterus.body);
  scenario.objects.push_back(uterus);
  scenario.session.gravity = Vec3::Zero();
  scenario.session.duration_limit = 60.0;
  scenario.session.procedure_definition = "diagnostic-hysteroscopy";
  scenario.session.instrument.kind = "hysteroscope";
  scenario.session.instrument.optics_angle = 30.0;
  scenario.session.force_warning = 0.05;
  const double r = kCavityRadius - 0.0005;
  const core::Vec3 right(r, 0.0, 0.004), left(-r, 0.0, 0.004);
  scenario.session.steps = {
      {"insert",
       "Insert",
       {{"pass-canal",
         "Pass the canal",
         {task("reach-os", "reach", {{"position", {0.0, 0.0, -0.004}}, {"radius", 0.004}})}}}},
      {"inspect",
       "Inspect",
       {{"panorama",
         "Panorama",
         {task("inspect-cavity", "inspect-surface",
               {{"object", "uterus"},
                {"region_attribute", "cavity"},
                {"region_value", 1},
                {"fraction", 0.35}})}},
        {"right",
         "Right orifice",
         {task("centre-right", "centre-target",
               {{"position", right},
                {"max_angle", 10},
                {"min_distance", 0.004},
                {"max_distance", 0.025},
                {"hold_time", 0.5}})}},
        {"left",
         "Left orifice",
         {task("centre-left", "centre-target",
               {{"position", left},
                {"max_angle", 10},
                {"min_distance", 0.004},
                {"max_distance", 0.025},
                {"hold_time", 0.5}})}}}},
      {"withdraw",
       "Withdraw",
       {{"out",
         "Out",
         {task("withdraw", "withdraw",
               {{"position", {0.0, 0.0, -0.010}},
                {"normal", {0.0, 0.0, -1.0}},
                {"margin", 0.002}})}}}}};
  return scenario;
}

}  // namespace

core::Scenario cavity_scenario() {
  static const core::Scenario scenario = build_cavity();
  return scenario;
}

nlohmann::json cavity_script(
    const std::vector<std::pair<double, std::pair<Vec3, Vec3>>>& waypoints) {
  nlohmann::json points = nlohmann::json::array();
  for (const auto& [t, pose] : waypoints)
    points.push_back({{"t", t}, {"tip", pose.first}, {"look_at", pose.second}});
  return {{"format", "viscera-script"}, {"version", 2},         {"body", "uterus"},
          {"stiffness", 200.0},         {"optics_angle", 30.0}, {"waypoints", points}};
}

nlohmann::json expert_cavity_script() {
  const Vec3 os(0.0, 0.0, -0.013), centre(0.0, 0.0, 0.0), up(0.0, 0.0, 0.02);
  std::vector<std::pair<double, std::pair<Vec3, Vec3>>> w = {
      {0.0, {os, up}}, {1.0, {{0.0, 0.0, -0.002}, up}}, {1.5, {centre, up}}};
  // Panorama: a ring of looks around the equator, one above and one below it.
  double t = 1.5;
  for (int k = 0; k < 8; ++k) {
    const double a = 2.0 * 3.141592653589793 * k / 8.0;
    w.push_back({t += 0.5, {centre, {std::cos(a) * 0.02, std::sin(a) * 0.02, 0.0}}});
  }
  for (int k = 0; k < 4; ++k) {
    const double a = 2.0 * 3.141592653589793 * k / 4.0 + 0.4;
    w.push_back({t += 0.5, {centre, {std::cos(a) * 0.014, std::sin(a) * 0.014, 0.014}}});
  }
  const Vec3 right(kCavityRadius - 0.0005, 0.0, 0.004), left(-kCavityRadius + 0.0005, 0.0, 0.004);
  w.push_back({t += 0.6, {{0.004, 0.0, 0.003}, right}});
  w.push_back({t += 1.0, {{0.004, 0.0, 0.003}, right}});
  w.push_back({t += 0.8, {{-0.004, 0.0, 0.003}, left}});
  w.push_back({t += 1.0, {{-0.004, 0.0, 0.003}, left}});
  w.push_back({t += 0.8, {centre, up}});
  w.push_back({t += 1.0, {os, up}});
  return cavity_script(w);
}

nlohmann::json novice_cavity_script() {
  const Vec3 os(0.0, 0.0, -0.013), up(0.0, 0.0, 0.02);
  const double r = kCavityRadius;
  const Vec3 right(r - 0.0005, 0.0, 0.004);
  std::vector<std::pair<double, std::pair<Vec3, Vec3>>> w = {
      {0.0, {os, up}},
      {1.5, {{0.003, 0.002, -0.004}, up}},
      {3.0, {{0.006, -0.004, 0.004}, {0.02, -0.01, 0.004}}},
      {4.5, {{r + 0.002, 0.0, 0.0}, {0.03, 0.0, 0.0}}},  // bumps the right wall
      {6.0, {{0.0, 0.004, 0.006}, {0.0, 0.02, 0.01}}},
      {7.5, {{-0.0043, r + 0.0025, 0.0011}, {0.0, 0.03, 0.0}}},  // and the front wall
      {9.0, {{-0.006, 0.0, 0.006}, {-0.02, 0.0, 0.02}}},
      {10.5, {{0.0012, 0.0007, r + 0.003}, {0.0, 0.0, 0.03}}},  // and the fundus, harder
      {12.0, {{0.006, 0.006, 0.002}, {0.01, 0.02, 0.0}}},
      // Looks at the right orifice from too close and at an angle, then wanders off.
      {14.0, {{0.012, 0.003, 0.004}, right + Vec3(0.0, 0.006, 0.004)}},
      {16.0, {{0.012, 0.003, 0.004}, right + Vec3(0.0, 0.006, 0.004)}},
      {18.0, {{0.0, -0.006, -0.004}, {0.0, -0.02, -0.01}}},
      {20.0, {{-0.005, 0.004, -0.006}, {-0.02, 0.0, -0.02}}},
      {23.0, {{0.002, 0.0, -0.004}, up}},
      {25.0, {os, up}},
  };
  return cavity_script(w);
}

}  // namespace viscera::testing
