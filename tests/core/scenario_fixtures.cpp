#include "tests/core/scenario_fixtures.h"

#include "core/mesh/surface_embedding.h"
#include "core/primitives/icosphere.h"

namespace viscera::testing {

core::TetMesh cube_body() {
  core::TetMesh mesh;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        mesh.nodes.emplace_back(0.01 * i, 0.01 * j, 0.01 * k);
  mesh.tets = {{0, 1, 2, 4}, {1, 3, 2, 7}, {1, 4, 7, 5}, {2, 7, 4, 6}, {1, 2, 4, 7}};
  core::orient_tets_positively(mesh);
  mesh.surface_faces = core::boundary_faces(mesh.tets);
  mesh.node_mass = core::lumped_node_masses(mesh, 1000.0);
  mesh.fixed.assign(mesh.nodes.size(), 0);
  mesh.fixed[0] = 1;
  mesh.tet_labels = {1, 2, 3, 4, 5};
  return mesh;
}

core::Scenario full_scenario() {
  core::Scenario s;
  s.metadata = {"full", "every field set", "tests"};
  s.procedure = "hysteroscopy";

  core::Material muscle;
  muscle.id = "myometrium";
  muscle.name = "Myometrium";
  muscle.density = 1060.0;
  muscle.distance_stiffness = 12000.0;
  muscle.area_stiffness = 3.5;
  muscle.volume_stiffness = 9000.0;
  muscle.distance_damping = 7.0;
  muscle.tearing_threshold = 0.45;
  muscle.plastic_yield = 0.25;
  muscle.stress_strain = core::StressStrainCurve{
      {0.0, 0.1, 0.2}, {0.0, 900.0, 2100.0}, {0.0, 8000.0, 1000.0, 500.0}, 12.5, 20.0};
  muscle.source = "synthetic";
  s.materials[muscle.id] = muscle;
  core::Material soft;
  soft.id = "soft";
  s.materials[soft.id] = soft;

  s.textures["wall"] = core::TextureSpec{"wall", "endometrium", 42, 256, 128, {}};

  core::SceneObject organ;
  organ.id = "uterus";
  organ.name = "Uterus";
  organ.role = core::ObjectRole::Organ;
  organ.material = "myometrium";
  organ.texture = "wall";
  organ.group = "pelvis";
  organ.body_kind = core::BodyKind::TetMesh;
  organ.body = cube_body();
  organ.surface.vertices = {
      {0.002, 0.002, 0.002}, {0.008, 0.002, 0.002}, {0.002, 0.008, 0.002}, {0.002, 0.002, 0.008}};
  organ.surface.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  organ.surface.normals = {{-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  organ.surface.uvs = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0.5}};
  organ.surface.vertex_attributes["wall_thickness"] = {0.01, 0.011, 0.012, 0.013};
  organ.embedding = core::embed_points(organ.surface.vertices, organ.body);
  // Three pressure states of the hydrometra (seed 000 §2.1), values that do not round trip
  // through text: the binary file must keep every bit.
  organ.hydrometra.pressures = {0.0, 1000.0 / 3.0, 2000.0};
  organ.hydrometra.node_count = static_cast<int>(organ.body.nodes.size());
  organ.hydrometra.residual = 1e-7 / 3.0;
  for (int k = 0; k < 3; ++k)
    for (int n = 0; n < organ.hydrometra.node_count; ++n)
      organ.hydrometra.displacements.push_back(core::Vec3(0.1 / 3.0, -n * 1e-3 / 7.0, k * 0.01) *
                                               static_cast<double>(k));
  s.objects.push_back(organ);

  core::SceneObject polyp;
  polyp.id = "polyp-1";
  polyp.name = "Polyp";
  polyp.role = core::ObjectRole::Pathology;
  polyp.material = "soft";
  polyp.body_kind = core::BodyKind::TetMesh;
  polyp.surface = core::make_icosphere(0.002, 1, core::Vec3(0.005, 0.005, 0.011));
  polyp.body = cube_body();
  for (auto& node : polyp.body.nodes)
    node = 0.3 * node + core::Vec3(0.0035, 0.0035, 0.0095);
  polyp.body.node_mass = core::lumped_node_masses(polyp.body, 1000.0);
  s.objects.push_back(polyp);

  core::VesselTree tree;
  tree.id = "arteries";
  tree.host_object = "uterus";
  tree.kind = "arterial";
  tree.segments = {{0, -1, {0, 0, 0}, {0.001, 0, 0}, 0.0005, 1e-7},
                   {1, 0, {0.001, 0, 0}, {0.002, 0.001, 0}, 0.0004, 5e-8}};
  s.vessel_trees.push_back(tree);
  s.active_deformations.push_back(
      {"pulse", "uterus", core::PulseSpec{"arteries", 72.0, 6.0, 0.04}});
  core::MotilitySpec motility;
  motility.amplitude_mean = 0.003;
  motility.amplitude_variance = 1e-6;
  motility.wave_speed = 0.02;
  motility.wave_direction = core::Vec3(0, 1, 0);
  motility.frequency = 0.2;
  motility.frequency_disturbance = 0.01;
  motility.contraction_interval_mean = 30.0;
  motility.contraction_interval_variance = 4.0;
  s.active_deformations.push_back({"motility", "uterus", motility});
  s.pathologies.push_back(
      {"p1", "polyp", "uterus", "polyp-1", core::Vec3(0.005, 0.005, 0.01), 0.004});
  s.connections.push_back({"stalk", "uterus", "polyp-1", {{5, 0}, {7, 1}}, 250.0});
  s.fluid = {true, "glycine", 12000.0, 500.0, 0.0015};
  s.session.time_step = 0.0005;
  s.session.contact_stiffness = 750.0;
  s.session.duration_limit = 300.0;
  s.session.gravity = core::Vec3(0, -9.81, 0);
  s.session.tasks.push_back({"look", "Inspect the cavity", "observe", {{"coverage", 0.8}}});
  s.session.metrics = {"duration", "path_length"};
  s.variability.push_back({"radius", "uniform", {{"low", 0.03}, {"high", 0.05}}});
  s.provenance.template_name = "hand-made";
  s.provenance.template_version = "7";
  s.provenance.seed = 99;
  s.provenance.parameters = {{"radius", 0.04}};
  s.provenance.tool_versions = {{"viscera", "test"}};
  return s;
}

}  // namespace viscera::testing
