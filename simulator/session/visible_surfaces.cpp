#include "simulator/session/visible_surfaces.h"

namespace viscera::sim {

VisibleSurfaces::VisibleSurfaces(const core::Scenario& scenario, const World& world)
    : objects_(world.models().size(), nullptr), cut_(world.models().size()) {
  for (const auto& model : world.models()) {
    const core::SceneObject* object = scenario.find_object(model->name);
    if (object == nullptr || object->surface.triangles.empty()) continue;
    if (object->embedding.tet.size() != object->surface.vertices.size()) continue;
    if (object->body.tets.size() != model->mesh.tets.size()) continue;
    objects_[static_cast<std::size_t>(model->body)] = object;
  }
}

cutting::TopologyChange VisibleSurfaces::cut(int body, const core::TetMesh& mesh,
                                             const std::vector<core::Vec3>& current,
                                             const cutting::CutSurface& surface,
                                             const cutting::HybridCutOptions& options) {
  const auto b = static_cast<std::size_t>(body);
  const core::SceneObject* object = objects_[b];
  if (object == nullptr) return cutting::hybrid_cut(mesh, current, surface, options);
  const CutVisibleSurface* last = cut_[b].get();
  cutting::TopologyChange change =
      last != nullptr
          ? cutting::hybrid_cut(mesh, current, surface, last->mesh, last->embedding, options)
          : cutting::hybrid_cut(mesh, current, surface, object->surface, object->embedding,
                                options);
  if (change.changed) {
    auto next = std::make_shared<CutVisibleSurface>();
    next->mesh = std::move(change.visual);
    next->embedding = std::move(change.visual_embedding);
    next->tets = change.mesh.tets;
    cut_[b] = std::move(next);
    // The change's visual fields moved into the kept surface: callers read the cut faces from
    // change.cut_surface_faces, which stays.
    change.visual = {};
    change.visual_embedding = {};
    change.visual_cut_triangles.clear();
  }
  return change;
}

void VisibleSurfaces::retire(int body, const BodyTopology& topology) {
  const auto b = static_cast<std::size_t>(body);
  const CutVisibleSurface* last = cut_[b].get();
  if (last == nullptr) return;
  std::vector<int> new_tet(last->tets.size(), -1);
  for (std::size_t t = 0; t < topology.tet_parent.size(); ++t)
    new_tet[static_cast<std::size_t>(topology.tet_parent[t])] = static_cast<int>(t);
  const core::SurfaceMesh& in = last->mesh;
  const auto kept_vertex = [&](int v) {
    return new_tet[static_cast<std::size_t>(last->embedding.tet[static_cast<std::size_t>(v)])] >= 0;
  };
  // Vertices of the kept triangles, in their old order.
  std::vector<int> new_vertex(in.vertices.size(), -1);
  auto next = std::make_shared<CutVisibleSurface>();
  for (const core::Triangle& t : in.triangles) {
    if (!(kept_vertex(t[0]) && kept_vertex(t[1]) && kept_vertex(t[2]))) continue;
    for (const int v : t)
      new_vertex[static_cast<std::size_t>(v)] = 0;
    next->mesh.triangles.push_back(t);
  }
  std::vector<int> order;
  for (std::size_t v = 0; v < in.vertices.size(); ++v) {
    if (new_vertex[v] < 0) continue;
    new_vertex[v] = static_cast<int>(order.size());
    order.push_back(static_cast<int>(v));
  }
  for (core::Triangle& t : next->mesh.triangles)
    for (int& v : t)
      v = new_vertex[static_cast<std::size_t>(v)];
  const auto pick = [&](const auto& from, auto& to) {
    if (from.empty()) return;
    to.reserve(order.size());
    for (const int v : order)
      to.push_back(from[static_cast<std::size_t>(v)]);
  };
  pick(in.vertices, next->mesh.vertices);
  pick(in.normals, next->mesh.normals);
  pick(in.uvs, next->mesh.uvs);
  for (const auto& [name, values] : in.vertex_attributes)
    pick(values, next->mesh.vertex_attributes[name]);
  pick(last->embedding.weights, next->embedding.weights);
  for (const int v : order)
    next->embedding.tet.push_back(
        new_tet[static_cast<std::size_t>(last->embedding.tet[static_cast<std::size_t>(v)])]);
  next->tets = topology.rest_mesh.tets;
  cut_[b] = std::move(next);
}

}  // namespace viscera::sim
