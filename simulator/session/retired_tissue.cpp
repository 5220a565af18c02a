#include "simulator/session/retired_tissue.h"

#include <cmath>
#include <vector>

namespace viscera::sim {

BodyTopology topology_without(const World& world, int body,
                              std::span<const cutting::Fragment> fragments) {
  const core::TetMesh& mesh = world.models()[static_cast<std::size_t>(body)]->mesh;
  const BodyTopology whole =
      unchanged_topology(mesh, world.state().range(world.state().positions, body));
  std::vector<std::uint8_t> retired_tet(mesh.tets.size(), 0), retired_node(mesh.nodes.size(), 0);
  for (const cutting::Fragment& f : fragments) {
    for (const int t : f.tets)
      retired_tet[static_cast<std::size_t>(t)] = 1;
    for (const int v : f.nodes)
      retired_node[static_cast<std::size_t>(v)] = 1;
  }
  BodyTopology out;
  out.rest_mesh.nodes = whole.rest_mesh.nodes;
  out.positions = whole.positions;
  out.origin = whole.origin;
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    if (retired_tet[t]) continue;
    out.rest_mesh.tets.push_back(mesh.tets[t]);
    out.tet_parent.push_back(static_cast<int>(t));
    if (!mesh.tet_labels.empty()) out.rest_mesh.tet_labels.push_back(mesh.tet_labels[t]);
  }
  // A fragment is a whole component: a face with one of its nodes is one of its faces.
  for (const core::Triangle& f : mesh.surface_faces) {
    if (!retired_node[static_cast<std::size_t>(f[0])]) out.rest_mesh.surface_faces.push_back(f);
  }
  if (!mesh.fixed.empty()) {
    out.rest_mesh.fixed = mesh.fixed;
    for (std::size_t v = 0; v < mesh.nodes.size(); ++v)
      out.rest_mesh.fixed[v] = out.rest_mesh.fixed[v] || retired_node[v];
  }
  // Without mass a node is fixed; masses lumped from the tets leave it none either.
  if (!mesh.node_mass.empty()) {
    out.rest_mesh.node_mass = mesh.node_mass;
    for (std::size_t v = 0; v < mesh.nodes.size(); ++v)
      if (retired_node[v]) out.rest_mesh.node_mass[v] = 0.0;
  }
  return out;
}

core::Vec3 fragment_centre(const cutting::Fragment& fragment,
                           std::span<const core::Vec3> positions) {
  core::Vec3 sum = core::Vec3::Zero();
  for (const int v : fragment.nodes)
    sum += positions[static_cast<std::size_t>(v)];
  return fragment.nodes.empty() ? sum : core::Vec3(sum / fragment.nodes.size());
}

double equivalent_radius(double volume) {
  return std::cbrt(3.0 * volume / (4.0 * M_PI));
}

}  // namespace viscera::sim
