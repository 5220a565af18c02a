#include "templates/agent_tissue/agent_tissue_template.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/random.h"
#include "core/scenario/procedure.h"
#include "templates/template_parts.h"
#include "templates/variability/parameter_distribution.h"

namespace viscera::templates {

std::string AgentTissueTemplate::description() const {
  return "sheet of cell agents (seed 003): soft matrix with random stiff inclusions, held at one "
         "edge, cell-type constants as data";
}

std::vector<TemplateParameter> AgentTissueTemplate::parameters() const {
  return {
      {"columns", "count", "cells along x", 4, 200, 40, true},
      {"rows", "count", "cells along y", 4, 200, 30, true},
      {"spacing", "m", "distance between neighbouring cells", 0.0005, 0.005, 0.001, false},
      {"inclusions", "count", "stiff inclusions in the sheet", 0, 10, 2, true},
      {"inclusion_radius", "m", "radius of each inclusion", 0.001, 0.02, 0.004, false},
      {"cell_mass", "kg", "mass of a cell", 1e-6, 1e-2, 1e-4, false},
      {"matrix_home_stiffness", "N/m", "k_home of matrix cells", 0.0, 10.0, 0.5, false},
      {"matrix_connection_stiffness", "N/m", "k_conn of matrix cells", 0.1, 200.0, 20.0, false},
      {"inclusion_connection_stiffness", "N/m", "k_conn of inclusion cells", 0.1, 1000.0, 100.0,
       false},
      {"damping", "1", "fraction of velocity removed per step", 0.0, 0.5, 0.05, false},
      {"tear_strain", "1", "matrix connections stretched beyond this break", 0.1, 5.0, 1.0, false},
      {"yield_strain", "1", "beyond this matrix rest lengths grow", 0.05, 5.0, 0.5, false},
      {"texture_seed", "count", "seed of the tissue texture", 0, 1e9, 1, true},
      {"texture_size", "count", "width and height of the baked maps in pixels", 64, 2048, 256,
       true},
  };
}

std::vector<core::VariabilityRule> AgentTissueTemplate::default_variability() const {
  return {integer_range_rule("inclusions", 1, 4), uniform_rule("inclusion_radius", 0.002, 0.006),
          truncated_normal_rule("matrix_connection_stiffness", 20.0, 4.0, 10.0, 30.0),
          truncated_normal_rule("inclusion_connection_stiffness", 100.0, 20.0, 50.0, 150.0),
          integer_range_rule("texture_seed", 0, 1000000000)};
}

core::Scenario AgentTissueTemplate::build(const ParameterValues& p, std::uint64_t seed,
                                          core::Progress& progress) const {
  progress.begin_stage("agent tissue sheet", 1);
  core::Rng rng(seed);
  const int nx = static_cast<int>(p.at("columns")), ny = static_cast<int>(p.at("rows"));
  const double s = p.at("spacing");
  if (p.at("yield_strain") >= p.at("tear_strain"))
    throw core::InputError("agent-tissue: the yield strain must be below the tear strain");

  core::CellTypeSpec matrix;
  matrix.id = "matrix";
  matrix.mass = p.at("cell_mass");
  matrix.radius = 0.5 * s;
  matrix.home_stiffness = p.at("matrix_home_stiffness");
  matrix.connection_stiffness = p.at("matrix_connection_stiffness");
  matrix.damping = p.at("damping");
  matrix.tear_strain = p.at("tear_strain");
  matrix.yield_strain = p.at("yield_strain");
  core::CellTypeSpec inclusion = matrix;
  inclusion.id = "inclusion";
  inclusion.connection_stiffness = p.at("inclusion_connection_stiffness");
  inclusion.tear_strain = 2.0 * matrix.tear_strain;  // fibrous: harder to tear
  inclusion.yield_strain = 2.0 * matrix.yield_strain;

  // Inclusion centres drawn uniformly over the sheet.
  std::vector<core::Vec3> centres;
  for (int k = 0; k < static_cast<int>(p.at("inclusions")); ++k)
    centres.emplace_back(rng.uniform(0.0, (nx - 1) * s), rng.uniform(0.0, (ny - 1) * s), 0.0);
  const double r = p.at("inclusion_radius");

  core::CellTissueSpec spec;
  spec.object = "tissue";
  spec.types = {matrix, inclusion};
  spec.neighbour_radius = 1.05 * s;
  spec.max_neighbours = 4;
  spec.planar = true;
  core::SceneObject sheet;
  sheet.id = "tissue";
  sheet.name = "Cell-agent tissue";
  sheet.role = core::ObjectRole::Organ;
  sheet.material = "tissue";
  sheet.texture = "tissue";
  sheet.body_kind = core::BodyKind::CellAgent;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const core::Vec3 x(i * s, j * s, 0.0);
      int type = 0;
      for (const auto& c : centres)
        type = (x - c).norm() <= r ? 1 : type;
      sheet.body.nodes.push_back(x);
      sheet.body.node_mass.push_back(spec.types[static_cast<std::size_t>(type)].mass);
      sheet.body.fixed.push_back(j == 0 ? 1 : 0);
      spec.cell_types.push_back(type);
    }
  }
  sheet.surface.vertices = sheet.body.nodes;
  sheet.surface.vertex_attributes["cell_type"] =
      std::vector<double>(spec.cell_types.begin(), spec.cell_types.end());
  for (int j = 0; j + 1 < ny; ++j) {
    for (int i = 0; i + 1 < nx; ++i) {
      const int a = j * nx + i, b = a + 1, c = a + nx, d = c + 1;
      sheet.surface.triangles.push_back({a, b, d});
      sheet.surface.triangles.push_back({a, d, c});
    }
  }
  core::compute_vertex_normals(sheet.surface);
  sheet.body.surface_faces = sheet.surface.triangles;

  core::Scenario scenario;
  scenario.metadata = {"agent-tissue", "Heterogeneous cell-agent tissue sheet (seed 003 §V).",
                       "viscera template agent-tissue"};
  scenario.procedure = procedure();
  // The cells carry their own constants; the material only names the tissue for the studio.
  add_material(scenario, "tissue", "Cell-agent tissue", 1000.0, 1000.0,
               "constants per cell type in cell_tissues (seed 003 §V)");
  add_texture(scenario, "tissue", "peritoneum", static_cast<std::uint64_t>(p.at("texture_seed")),
              static_cast<int>(p.at("texture_size")));
  scenario.objects.push_back(std::move(sheet));
  scenario.cell_tissues.push_back(std::move(spec));
  scenario.session.gravity = core::Vec3::Zero();
  // Seed 003 §V: palpate, pull with the grasper and cut with the scissors (removing the links
  // the blades cross): a laparoscope whose working port carries the tools.
  core::apply_procedure(scenario.session, core::procedure_definition("agent-tissue-lab"));
  // The cells integrate explicitly (seed 003 eq. 6–7): stable while ω h < 2 with ω² of a cell
  // pulled by its four neighbours and its home, (4 k_conn + k_home) / m. Half that step, and
  // never above the 1 ms default.
  double stiffest = 0.0;
  for (const auto& type : scenario.cell_tissues.back().types) {
    stiffest =
        std::max(stiffest, (4.0 * type.connection_stiffness + type.home_stiffness) / type.mass);
  }
  scenario.session.time_step = std::min(1e-3, 1.0 / std::sqrt(stiffest));
  progress.step();
  return scenario;
}

}  // namespace viscera::templates
