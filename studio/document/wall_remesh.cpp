#include "studio/document/wall_remesh.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/mesh/surface_embedding.h"
#include "core/meshing/tet_mesher.h"
#include "simulator/dynamics/hydrometra_sweep.h"
#include "textures/scenario_baking.h"

namespace viscera::studio {
namespace {

const core::Vec3& node(const core::TetMesh& body, int n) {
  return body.nodes[static_cast<std::size_t>(n)];
}

/// For each point, the corner nearest to it of the tet of `body` that holds it.
std::vector<int> nearest_corners(const std::vector<core::Vec3>& points, const core::TetMesh& body) {
  const core::SurfaceEmbedding located = core::embed_points(points, body);
  std::vector<int> corners(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& tet = body.tets[static_cast<std::size_t>(located.tet[i])];
    corners[i] = *std::min_element(tet.begin(), tet.end(), [&](int a, int b) {
      return (node(body, a) - points[i]).squaredNorm() < (node(body, b) - points[i]).squaredNorm();
    });
  }
  return corners;
}

core::Vec3 centroid(const core::TetMesh& body, const core::Tetrahedron& tet) {
  return 0.25 * (node(body, tet[0]) + node(body, tet[1]) + node(body, tet[2]) + node(body, tet[3]));
}

/// The old body's mean density, kg/m³: its total mass over its volume (0 without masses).
double mean_density(const core::TetMesh& body) {
  double mass = 0.0;
  for (const double m : body.node_mass)
    mass += m;
  const double volume = core::total_volume(body);
  return volume > 0.0 ? mass / volume : 0.0;
}

/// Lumped masses with each tet's density from its layer material.
std::vector<double> layered_masses(const core::Scenario& scenario, const core::SceneObject& host,
                                   const core::TetMesh& body, double fallback_density) {
  const auto density_of = [&](int label) {
    const auto layer = host.layer_materials.find(label);
    const std::string& id = layer != host.layer_materials.end() ? layer->second : host.material;
    const auto material = scenario.materials.find(id);
    return material != scenario.materials.end() ? material->second.density : fallback_density;
  };
  std::vector<double> mass(body.nodes.size(), 0.0);
  for (std::size_t t = 0; t < body.tets.size(); ++t) {
    const int label = body.tet_labels.empty() ? 0 : body.tet_labels[t];
    const double quarter =
        0.25 * density_of(label) * std::abs(core::signed_volume(body, static_cast<int>(t)));
    for (const int n : body.tets[t])
      mass[static_cast<std::size_t>(n)] += quarter;
  }
  return mass;
}

}  // namespace

RemeshedHost remesh_around_holes(const core::Scenario& scenario, const std::string& host_id,
                                 const std::vector<core::SurfaceMesh>& holes,
                                 core::Progress& progress) {
  const core::SceneObject* found = scenario.find_object(host_id);
  if (found == nullptr) throw core::UsageError("the scenario has no object \"" + host_id + "\"");
  const core::SceneObject& host = *found;
  if (host.body_kind != core::BodyKind::TetMesh || host.body.tets.empty())
    throw core::UsageError("object \"" + host_id + "\" has no tet body to hold a pathology");
  const core::TetMesh& old_body = host.body;

  // The holes already in the wall stay holes: the intramural pathologies it holds.
  std::vector<core::SurfaceMesh> all_holes;
  for (const auto& pathology : scenario.pathologies) {
    if (pathology.host_object != host_id || pathology.kind != "myoma-intramural") continue;
    if (const core::SceneObject* inside = scenario.find_object(pathology.object))
      all_holes.push_back(textures::welded_surface(inside->surface));
  }
  all_holes.insert(all_holes.end(), holes.begin(), holes.end());

  RemeshedHost rebuilt;
  rebuilt.object = host;
  core::TetMesh& body = rebuilt.object.body;
  body = core::mesh_region_between(textures::welded_surface(host.surface), all_holes, {}, progress);

  if (!old_body.tet_labels.empty()) {
    std::vector<core::Vec3> centres;
    centres.reserve(body.tets.size());
    for (const auto& tet : body.tets)
      centres.push_back(centroid(body, tet));
    const core::SurfaceEmbedding located = core::embed_points(centres, old_body);
    body.tet_labels.resize(body.tets.size());
    for (std::size_t t = 0; t < body.tets.size(); ++t)
      body.tet_labels[t] = old_body.tet_labels[static_cast<std::size_t>(located.tet[t])];
  }
  if (!old_body.fixed.empty()) {
    const std::vector<int> from = nearest_corners(body.nodes, old_body);
    body.fixed.resize(body.nodes.size());
    for (std::size_t n = 0; n < body.nodes.size(); ++n)
      body.fixed[n] = old_body.fixed[static_cast<std::size_t>(from[n])];
  }
  body.node_mass = layered_masses(scenario, host, body, mean_density(old_body));
  rebuilt.object.embedding = core::embed_points(host.surface.vertices, body);

  // Connections hold host knots by index: each moves to the new knot nearest to the old one.
  for (const auto& connection : scenario.connections) {
    const bool a = connection.object_a == host_id, b = connection.object_b == host_id;
    if (!a && !b) continue;
    core::Connection moved = connection;
    for (const int side : {0, 1}) {
      if (!(side == 0 ? a : b)) continue;
      std::vector<core::Vec3> knots;
      for (const auto& pair : moved.node_pairs)
        knots.push_back(node(old_body, pair[static_cast<std::size_t>(side)]));
      const std::vector<int> to = nearest_corners(knots, body);
      for (std::size_t k = 0; k < moved.node_pairs.size(); ++k)
        moved.node_pairs[k][static_cast<std::size_t>(side)] = to[k];
    }
    rebuilt.connections.push_back(std::move(moved));
  }
  // The old body's pressure states do not fit the new one: the sweep runs again (seed 000 §2.1).
  if (!host.hydrometra.empty())
    rebuilt.object.hydrometra =
        sim::sweep_hydrometra(rebuilt.object, scenario.materials, {}, progress);
  return rebuilt;
}

}  // namespace viscera::studio
