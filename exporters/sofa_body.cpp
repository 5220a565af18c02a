#include "exporters/sofa_body.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "core/error.h"

namespace viscera::exporters {
namespace {

/// Refuses the body kinds whose model SOFA cannot run, with what to do instead.
void check_exportable(const ExportObject& object) {
  const core::BodyKind kind = object.source->body_kind;
  const char* what = nullptr;
  if (kind == core::BodyKind::UrethraLattice)
    what =
        "a urethra lattice (seed 002), whose force model acts on the endoscope (friction and "
        "wall springs along its axis)";
  if (kind == core::BodyKind::CellAgent)
    what = "cell-agent tissue (seed 003), whose neighbour links form at run time";
  if (what == nullptr) return;
  throw core::UsageError("object \"" + object.id() + "\" is " + what +
                         " and has no SOFA counterpart; export the other objects with --object, "
                         "or this one as a mesh (--format vtk or msh)");
}

std::vector<double> uniform_or_per_tet(const std::vector<double>& values) {
  if (values.empty()) return values;
  for (const double v : values)
    if (v != values.front()) return values;
  return {values.front()};
}

/// FEM parameters per tet, and the Teschner-equivalent stiffness each tet adds to its nodes'
/// rows (edge springs (s_D + 2 s_V) V/6 / l0², an upper estimate of the volume term's share).
void add_elasticity(const core::Scenario& scenario, SofaBody& body) {
  const core::SceneObject& object = *body.object->source;
  std::vector<double> young, poisson;
  for (std::size_t t = 0; t < object.body.tets.size(); ++t) {
    const core::Material& material = tet_material(scenario, object, t);
    const SofaElasticity e = sofa_elasticity(material);
    young.push_back(e.young_modulus);
    poisson.push_back(e.poisson_ratio);
    const auto& tet = object.body.tets[t];
    const double share = core::signed_volume(object.body, static_cast<int>(t)) / 6.0;
    for (int a = 0; a < 4; ++a) {
      for (int b = a + 1; b < 4; ++b) {
        const double l2 = (object.body.nodes[static_cast<std::size_t>(tet[b])] -
                           object.body.nodes[static_cast<std::size_t>(tet[a])])
                              .squaredNorm();
        const double k =
            (material.distance_stiffness + 2.0 * std::max(material.volume_stiffness, 0.0)) * share /
            l2;
        body.node_stiffness[static_cast<std::size_t>(tet[a])] += 2.0 * k;
        body.node_stiffness[static_cast<std::size_t>(tet[b])] += 2.0 * k;
      }
    }
  }
  body.young_modulus = uniform_or_per_tet(young);
  body.poisson_ratio = uniform_or_per_tet(poisson);
}

void add_springs(const core::Scenario& scenario, SofaBody& body) {
  body.springs = kismo_springs(scenario, *body.object->source);
  body.tetrahedra_stiffness = uniform_tetrahedra_stiffness(body.springs, 1e-3);
  for (auto& spring : body.springs) {
    body.node_stiffness[static_cast<std::size_t>(spring.a)] += 2.0 * spring.stiffness;
    body.node_stiffness[static_cast<std::size_t>(spring.b)] += 2.0 * spring.stiffness;
    spring.damping = 0.0;  // carried by the solver's Rayleigh β (sofa_material.h)
  }
}

void add_masses(const core::Scenario& scenario, SofaBody& body) {
  const core::SceneObject& object = *body.object->source;
  const core::TetMesh& mesh = object.body;
  std::vector<double> tet_density;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const core::Material& material = tet_material(scenario, object, t);
    tet_density.push_back(material.density);
    body.tet_mass.push_back(material.density * core::signed_volume(mesh, static_cast<int>(t)));
    body.tet_rayleigh.push_back(rayleigh_stiffness(material, body.mass_spring));
  }
  // DiagonalMass massDensity lumps a quarter of ρV of each tet on its nodes, like
  // core::lumped_node_masses; it is written when that gives the package's masses.
  const bool one_density = std::all_of(tet_density.begin(), tet_density.end(),
                                       [&](double d) { return d == tet_density.front(); });
  const std::vector<double> lumped = core::lumped_node_masses(mesh, tet_density.front());
  body.masses = mesh.node_mass.empty() ? lumped : mesh.node_mass;
  bool same = one_density && body.masses.size() == lumped.size();
  for (std::size_t i = 0; same && i < lumped.size(); ++i)
    same = std::abs(lumped[i] - body.masses[i]) <= 1e-9 * std::max(std::abs(lumped[i]), 1e-30);
  if (same) body.mass_density = tet_density.front();
}

}  // namespace

std::vector<SofaBody> sofa_bodies(const core::Scenario& scenario,
                                  const std::vector<ExportObject>& objects) {
  std::vector<SofaBody> bodies;
  for (const auto& object : objects) {
    check_exportable(object);
    if (!object.has_body()) continue;
    SofaBody body;
    body.object = &object;
    body.mass_spring = object.source->body_kind == core::BodyKind::MassSpring;
    body.node_stiffness.assign(object.source->body.nodes.size(), 0.0);
    add_masses(scenario, body);
    if (body.mass_spring)
      add_springs(scenario, body);
    else
      add_elasticity(scenario, body);
    bodies.push_back(std::move(body));
  }
  // Attached nodes are held by their springs, not fixed in space.
  std::vector<std::set<int>> attached(bodies.size());
  for (const core::Connection* connection : exported_connections(scenario, bodies)) {
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (bodies[b].object->id() != connection->object_b) continue;
      for (const auto& pair : connection->node_pairs)
        attached[b].insert(pair[1]);
    }
  }
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const auto& flags = bodies[b].object->source->body.fixed;
    for (std::size_t i = 0; i < flags.size(); ++i) {
      if (flags[i] != 0 && !attached[b].contains(static_cast<int>(i)))
        bodies[b].fixed.push_back(static_cast<int>(i));
    }
    bodies[b].attached.assign(attached[b].begin(), attached[b].end());
    bodies[b].all_fixed = bodies[b].fixed.size() == bodies[b].masses.size();
  }
  return bodies;
}

std::vector<const core::Connection*> exported_connections(const core::Scenario& scenario,
                                                          const std::vector<SofaBody>& bodies) {
  std::vector<const core::Connection*> connections;
  for (const auto& connection : scenario.connections) {
    if (find_body(bodies, connection.object_a) != nullptr &&
        find_body(bodies, connection.object_b) != nullptr)
      connections.push_back(&connection);
  }
  return connections;
}

const SofaBody* find_body(const std::vector<SofaBody>& bodies, const std::string& id) {
  for (const auto& body : bodies) {
    if (body.object->id() == id) return &body;
  }
  return nullptr;
}

}  // namespace viscera::exporters
