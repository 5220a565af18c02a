#include "templates/template_parts.h"

#include <algorithm>
#include <map>

#include "core/error.h"
#include "core/mesh/tet_quality.h"
#include "core/meshing/tet_mesher.h"
#include "core/modelling/layered_body.h"
#include "core/modelling/object_connectivity.h"

namespace viscera::templates {
namespace {

/// Tets below this smallest dihedral angle, in degrees, that lie flat on the boundary are
/// removed from small bodies (remove_boundary_slivers).
constexpr double kBoundarySliverDegrees = 3.0;

}  // namespace

std::size_t remove_boundary_slivers(core::TetMesh& body, std::size_t surface_nodes,
                                    double min_dihedral_degrees) {
  std::map<std::array<int, 3>, int> face_use;
  const auto key = [](int a, int b, int c) {
    std::array<int, 3> k{a, b, c};
    std::sort(k.begin(), k.end());
    return k;
  };
  std::vector<int> node_use(body.nodes.size(), 0);
  for (const auto& t : body.tets) {
    for (const int n : t)
      ++node_use[static_cast<std::size_t>(n)];
    ++face_use[key(t[1], t[2], t[3])];
    ++face_use[key(t[0], t[2], t[3])];
    ++face_use[key(t[0], t[1], t[3])];
    ++face_use[key(t[0], t[1], t[2])];
  }
  std::vector<core::Tetrahedron> kept;
  std::size_t removed = 0;
  for (const auto& t : body.tets) {
    const auto& x = body.nodes;
    const core::TetShape shape = core::tet_shape(x[t[0]], x[t[1]], x[t[2]], x[t[3]]);
    int boundary = 0;
    boundary += face_use[key(t[1], t[2], t[3])] == 1;
    boundary += face_use[key(t[0], t[2], t[3])] == 1;
    boundary += face_use[key(t[0], t[1], t[3])] == 1;
    boundary += face_use[key(t[0], t[1], t[2])] == 1;
    bool on_surface = true, shared = true;
    for (const int n : t) {
      on_surface = on_surface && static_cast<std::size_t>(n) < surface_nodes;
      shared = shared && node_use[static_cast<std::size_t>(n)] > 1;
    }
    if (shape.min_dihedral_degrees < min_dihedral_degrees && boundary == 2 && on_surface &&
        shared) {
      for (const int n : t)
        --node_use[static_cast<std::size_t>(n)];
      ++removed;
      continue;
    }
    kept.push_back(t);
  }
  if (removed == 0) return 0;
  // Labels follow their tets; the boundary now runs over the removed slivers' inner faces.
  if (!body.tet_labels.empty()) {
    std::vector<int> labels;
    std::size_t j = 0;
    for (std::size_t i = 0; i < body.tets.size() && j < kept.size(); ++i) {
      if (body.tets[i] == kept[j]) labels.push_back(body.tet_labels[i]), ++j;
    }
    body.tet_labels = std::move(labels);
  }
  body.tets = std::move(kept);
  body.surface_faces = core::boundary_faces(body.tets);
  return removed;
}

void add_material(core::Scenario& scenario, const std::string& id, const std::string& name,
                  double density, double stiffness, const std::string& source) {
  core::Material m;
  m.id = id;
  m.name = name;
  m.density = density;
  m.distance_stiffness = stiffness;
  m.volume_stiffness = stiffness;
  m.area_stiffness = 0.0;
  m.distance_damping = 2e-4 * stiffness;
  m.source = source;
  scenario.materials[id] = m;
}

void add_texture(core::Scenario& scenario, const std::string& id, const std::string& preset,
                 std::uint64_t seed, int size) {
  core::TextureSpec spec;
  spec.id = id;
  spec.preset = preset;
  spec.seed = seed;
  spec.width = spec.height = size;
  scenario.textures[id] = spec;
}

core::SceneObject& add_tet_object(core::Scenario& scenario, const std::string& id,
                                  const std::string& name, core::ObjectRole role,
                                  const std::string& material, const std::string& texture,
                                  const core::SurfaceMesh& surface, double density,
                                  core::Progress& progress) {
  core::SceneObject object;
  object.id = id;
  object.name = name;
  object.role = role;
  object.material = material;
  object.texture = texture;
  object.body_kind = core::BodyKind::TetMesh;
  object.surface = surface;
  try {
    object.body = core::mesh_closed_surface(surface, {}, progress);
    remove_boundary_slivers(object.body, surface.vertices.size(), kBoundarySliverDegrees);
  } catch (const core::InputError& e) {
    throw core::InputError("object " + id + ": " + e.reason());
  }
  object.body.node_mass = core::lumped_node_masses(object.body, density);
  object.body.fixed.assign(object.body.nodes.size(), 0);
  object.embedding = core::embed_leading_nodes(object.body, surface.vertices.size());
  scenario.objects.push_back(std::move(object));
  return scenario.objects.back();
}

void attach(core::Scenario& scenario, const std::string& host, const std::string& part,
            const std::vector<int>& part_nodes, double within, double stiffness) {
  const core::SceneObject* host_object = scenario.find_object(host);
  core::SceneObject* part_object = nullptr;
  for (auto& object : scenario.objects) {
    if (object.id == part) part_object = &object;
  }
  if (host_object == nullptr || part_object == nullptr)
    throw core::UsageError("attach: unknown object " + host + " or " + part);
  std::vector<core::Vec3> base;
  for (const int n : part_nodes)
    base.push_back(part_object->body.nodes.at(static_cast<std::size_t>(n)));
  core::Connection connection;
  connection.id = host + "-" + part;
  connection.object_a = host;
  connection.object_b = part;
  connection.stiffness = stiffness;
  for (const auto& [h, b] : core::nearest_knot_pairs(host_object->body.nodes, base, within)) {
    connection.node_pairs.push_back({h, part_nodes[static_cast<std::size_t>(b)]});
  }
  if (connection.node_pairs.size() < 3) {
    throw core::InputError(part + " is not attached to " + host + ": " +
                           std::to_string(connection.node_pairs.size()) + " knot pairs within " +
                           std::to_string(within * 1000.0) + " mm");
  }
  scenario.connections.push_back(std::move(connection));
}

}  // namespace viscera::templates
