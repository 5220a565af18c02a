#include "templates/ball_template.h"

#include "core/meshing/tet_mesher.h"
#include "core/primitives/box.h"
#include "core/primitives/icosphere.h"

namespace viscera::templates {

std::string BallTemplate::description() const {
  return "spherical organ on a fixed base: icosphere surface, gmsh tetrahedral body, soft tissue";
}

std::vector<TemplateParameter> BallTemplate::parameters() const {
  return {
      {"radius", "m", "radius of the ball", 0.005, 0.2, 0.04, false},
      {"cell_size", "m", "target tetrahedron edge length of the body", 0.002, 0.05, 0.008, false},
      {"visual_subdivisions", "count",
       "extra icosphere subdivisions of the visual surface over the body's", 0, 2, 1, true},
      {"fixed_base_height", "1", "height of the fixed base slice as a fraction of the diameter",
       0.0, 0.5, 0.1, false},
      {"density", "kg/m^3", "tissue density", 500.0, 2000.0, 1050.0, false},
      {"distance_stiffness", "Pa", "Teschner distance stiffness density", 100.0, 1.0e6, 30000.0,
       false},
      {"volume_stiffness", "Pa", "Teschner volume stiffness density", 0.0, 1.0e6, 30000.0, false},
      {"area_stiffness", "N/m", "Teschner surface area stiffness density", 0.0, 1.0e3, 2.0, false},
      {"distance_damping", "Pa*s", "damping density on distance terms", 0.0, 1.0e3, 100.0, false},
      {"floor", "count",
       "1: the ball rests free on a fixed tissue slab (two touching bodies) instead of a fixed "
       "base",
       0, 1, 0, true},
  };
}

namespace {

/// A fixed slab of stiff tissue whose top face touches the bottom of the ball (z = −radius).
void add_floor(core::Scenario& scenario, double radius, double cell_size,
               core::Progress& progress) {
  core::Material slab;
  slab.id = "floor-tissue";
  slab.name = "Stiff supporting tissue";
  slab.density = 1100.0;
  slab.distance_stiffness = 3.0e5;
  slab.volume_stiffness = 3.0e5;
  slab.distance_damping = 100.0;
  slab.source = "ten times the ball's stiffness, so the ball does the deforming";
  scenario.materials[slab.id] = slab;

  const core::Vec3 min(-2.0 * radius, -2.0 * radius, -1.5 * radius);
  const core::Vec3 max(2.0 * radius, 2.0 * radius, -radius);
  core::SceneObject floor;
  floor.id = "floor";
  floor.name = "Floor";
  floor.role = core::ObjectRole::Fixture;
  floor.material = slab.id;
  floor.body_kind = core::BodyKind::TetMesh;
  floor.surface = core::make_box(min, max, 2.0 * cell_size);
  core::TetMeshingOptions meshing;
  meshing.cell_size = 2.0 * cell_size;
  floor.body = core::mesh_closed_surface(floor.surface, meshing, progress);
  floor.body.node_mass = core::lumped_node_masses(floor.body, slab.density);
  floor.body.fixed.assign(floor.body.nodes.size(), 1);  // the slab holds still
  floor.embedding = core::embed_points(floor.surface.vertices, floor.body);
  scenario.objects.push_back(std::move(floor));
}

}  // namespace

core::Scenario BallTemplate::build(const ParameterValues& p, std::uint64_t /*seed*/,
                                   core::Progress& progress) const {
  const double radius = p.at("radius");
  const double cell_size = p.at("cell_size");

  core::Scenario scenario;
  scenario.metadata.name = "ball";
  scenario.metadata.description = "A soft spherical organ resting on its fixed base.";
  scenario.metadata.author = "viscera template ball";
  scenario.procedure = procedure();

  core::Material tissue;
  tissue.id = "soft-tissue";
  tissue.name = "Generic soft tissue";
  tissue.density = p.at("density");
  tissue.distance_stiffness = p.at("distance_stiffness");
  tissue.volume_stiffness = p.at("volume_stiffness");
  tissue.area_stiffness = p.at("area_stiffness");
  tissue.distance_damping = p.at("distance_damping");
  tissue.source =
      "effective modulus about a fifth of distance_stiffness (edge-spring network), i.e. ~6 kPa, "
      "the order of soft abdominal tissue; density of water-rich tissue";
  scenario.materials[tissue.id] = tissue;

  // The body surface is an icosphere whose edges match the cell size; the visual surface is
  // the same sphere refined further and rides on the body through its embedding.
  const int body_level = core::icosphere_subdivisions_for_edge(radius, cell_size);
  const core::SurfaceMesh body_surface = core::make_icosphere(radius, body_level);
  core::TetMeshingOptions meshing;
  meshing.cell_size = cell_size;
  core::TetMesh body = core::mesh_closed_surface(body_surface, meshing, progress);
  body.node_mass = core::lumped_node_masses(body, tissue.density);

  const bool on_floor = p.at("floor") != 0.0;
  const double fixed_below = -radius + 2.0 * radius * p.at("fixed_base_height");
  body.fixed.assign(body.nodes.size(), 0);
  for (std::size_t n = 0; n < body.nodes.size() && !on_floor; ++n) {
    if (body.nodes[n].z() <= fixed_below) body.fixed[n] = 1;
  }

  core::SceneObject ball;
  ball.id = "ball";
  ball.name = "Ball";
  ball.role = core::ObjectRole::Organ;
  ball.material = tissue.id;
  ball.body_kind = core::BodyKind::TetMesh;
  const int visual_level = std::min(7, body_level + static_cast<int>(p.at("visual_subdivisions")));
  ball.surface = core::make_icosphere(radius, visual_level);
  ball.embedding = core::embed_points(ball.surface.vertices, body);
  ball.body = std::move(body);
  scenario.objects.push_back(std::move(ball));
  if (on_floor) add_floor(scenario, radius, cell_size, progress);

  core::TaskSpec settle;
  settle.id = "settle";
  settle.name = "Let the organ settle under gravity";
  settle.kind = "settle";
  // Kinetic energy below 1 µJ for 0.1 s counts as at rest for a ball of ~0.3 kg.
  settle.parameters = {{"kinetic_energy_below", 1.0e-6}, {"hold_time", 0.1}};
  scenario.session.tasks.push_back(settle);
  scenario.session.duration_limit = 10.0;
  scenario.session.metrics = {"max_displacement", "kinetic_energy", "potential_energy"};
  return scenario;
}

}  // namespace viscera::templates
