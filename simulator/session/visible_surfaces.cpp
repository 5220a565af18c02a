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

}  // namespace viscera::sim
