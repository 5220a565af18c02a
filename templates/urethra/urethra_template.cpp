#include "templates/urethra/urethra_template.h"

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "core/scenario/procedure.h"
#include "templates/template_parts.h"
#include "templates/variability/parameter_distribution.h"

namespace viscera::templates {

std::string UrethraTemplate::description() const {
  return "urethra lattice on the parabolic centre line y = a z^2 (seed 002): w sections of n "
         "points, fixed bladder entrance, force-model constants";
}

std::vector<TemplateParameter> UrethraTemplate::parameters() const {
  return {
      {"curvature", "1/m", "a of the centre line y = a z^2 (seed 002: 0.13 per cm)", 5.0, 25.0,
       13.0, false},
      {"length", "m", "meatus to bladder entrance along z", 0.1, 0.22, 0.16, false},
      {"radius", "m", "undeformed lumen radius", 0.0005, 0.003, 0.001, false},
      {"points_per_section", "count", "n: points of each circular section", 5, 32, 9, true},
      {"sections", "count", "w: sections from meatus to bladder entrance", 5, 100, 26, true},
      {"wall_thickness", "m", "wall thickness (node masses)", 0.0005, 0.004, 0.002, false},
      {"density", "kg/m^3", "wall density (node masses)", 900, 1200, 1050, false},
      {"endoscope_radius", "m", "cystoscope shaft radius (seed 002: 4x the urethra's)", 0.001,
       0.008, 0.004, false},
      {"spring_stiffness", "N/m", "k of each of the n - 1 wall springs per section", 1, 100, 15,
       false},
      {"friction", "1", "Coulomb friction coefficient", 0.0, 1.0, 0.3, false},
      {"viscous_friction", "N*s/m", "viscous friction along the axis", 0.0, 10.0, 2.0, false},
      {"break_force", "N", "axial force that tears the tissue", 0.5, 20.0, 4.0, false},
      {"break_torque", "N*m", "torque that tears the tissue", 0.01, 0.5, 0.08, false},
      {"texture_seed", "count", "seed of the mucosa texture", 0, 1e9, 1, true},
      {"texture_size", "count", "width and height of the baked maps in pixels", 64, 2048, 256,
       true},
  };
}

std::vector<core::VariabilityRule> UrethraTemplate::default_variability() const {
  return {truncated_normal_rule("curvature", 13.0, 2.0, 8.0, 18.0),
          truncated_normal_rule("length", 0.16, 0.015, 0.13, 0.2),
          uniform_rule("radius", 0.0008, 0.0015),
          truncated_normal_rule("spring_stiffness", 15.0, 3.0, 8.0, 25.0),
          uniform_rule("friction", 0.2, 0.4),
          integer_range_rule("texture_seed", 0, 1000000000)};
}

core::Scenario UrethraTemplate::build(const ParameterValues& p, std::uint64_t seed,
                                      core::Progress& progress) const {
  progress.begin_stage("urethra lattice", 1);
  core::UrethraLatticeSpec spec;
  spec.object = "urethra";
  spec.curvature = p.at("curvature");
  spec.length = p.at("length");
  spec.radius = p.at("radius");
  spec.points_per_section = static_cast<int>(p.at("points_per_section"));
  spec.sections = static_cast<int>(p.at("sections"));
  spec.endoscope_radius = p.at("endoscope_radius");
  spec.spring_stiffness = p.at("spring_stiffness");
  spec.friction = p.at("friction");
  spec.viscous_friction = p.at("viscous_friction");
  spec.break_force = p.at("break_force");
  spec.break_torque = p.at("break_torque");
  if (spec.endoscope_radius <= spec.radius)
    throw core::InputError("urethra: the endoscope must be wider than the undeformed lumen");

  const int n = spec.points_per_section, w = spec.sections;
  const double a = spec.curvature, dz = spec.length / (w - 1);
  // Wall mass of one section's share, spread over its n points.
  const double node_mass =
      p.at("density") * 2.0 * std::numbers::pi * spec.radius * p.at("wall_thickness") * dz / n;
  core::SceneObject urethra;
  urethra.id = "urethra";
  urethra.name = "Urethra";
  urethra.role = core::ObjectRole::Organ;
  urethra.material = "urethra";
  urethra.texture = "urethra";
  urethra.body_kind = core::BodyKind::UrethraLattice;
  for (int j = 0; j < w; ++j) {
    const double z = j * dz;
    const core::Vec3 centre(0.0, a * z * z, z);
    // The section plane is normal to the tangent (0, 2 a z, 1): x stays, y tilts about x.
    const core::Vec3 tangent = core::Vec3(0.0, 2.0 * a * z, 1.0).normalized();
    const core::Vec3 side = core::Vec3::UnitX();
    const core::Vec3 up = tangent.cross(side);
    for (int i = 0; i < n; ++i) {
      const double phi = 2.0 * std::numbers::pi * i / n;
      urethra.body.nodes.push_back(centre +
                                   spec.radius * (std::cos(phi) * side + std::sin(phi) * up));
      urethra.body.fixed.push_back(j == w - 1 ? 1 : 0);  // the bladder entrance
      urethra.body.node_mass.push_back(node_mass);
    }
  }
  // The visual surface is the open tube through the lattice points, lumen facing inward.
  urethra.surface.vertices = urethra.body.nodes;
  for (int j = 0; j + 1 < w; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a0 = j * n + i, a1 = j * n + (i + 1) % n, b0 = a0 + n, b1 = a1 + n;
      urethra.surface.triangles.push_back({a0, b0, a1});
      urethra.surface.triangles.push_back({a1, b0, b1});
    }
  }
  core::compute_vertex_normals(urethra.surface);
  urethra.body.surface_faces = urethra.surface.triangles;

  core::Scenario scenario;
  scenario.metadata = {"urethra", "Urethra lattice for urethral endoscopy (seed 002).",
                       "viscera template urethra"};
  scenario.procedure = procedure();
  add_material(scenario, "urethra", "Urethral wall", p.at("density"), 5000.0,
               "soft mucosal tube; the force model (spring_stiffness, friction) sets the feel");
  add_texture(scenario, "urethra", "urethral-mucosa",
              static_cast<std::uint64_t>(p.at("texture_seed")),
              static_cast<int>(p.at("texture_size")));
  scenario.objects.push_back(std::move(urethra));
  scenario.urethra_lattices.push_back(spec);
  scenario.landmarks.push_back({"urethral-meatus", "External urethral meatus", "urethra",
                                core::Vec3::Zero(), -core::Vec3::UnitZ()});
  scenario.landmarks.push_back({"bladder-entrance", "Bladder entrance", "urethra",
                                core::Vec3(0.0, a * spec.length * spec.length, spec.length),
                                core::Vec3(0.0, 2.0 * a * spec.length, 1.0).normalized()});
  scenario.session.gravity = core::Vec3::Zero();
  // Seed 002 §3, §5: insertion from the meatus to the bladder entrance and back, with the
  // endoscope of this lattice (its shaft sets the lumen's deformation).
  core::apply_procedure(scenario.session,
                        core::procedure_definition("urethral-endoscope-insertion"));
  scenario.session.instrument.shaft_diameter = 2.0 * spec.endoscope_radius;
  (void)seed;  // the lattice is fully set by its parameters; the seed goes to provenance
  progress.step();
  return scenario;
}

}  // namespace viscera::templates
