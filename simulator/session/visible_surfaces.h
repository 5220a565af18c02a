#pragma once
/// The visible surfaces of the bodies a session cuts (issue 17 §2; seed 000 §9: the
/// high-resolution surface "is mapped to the lower resolution tetrahedral model and updated
/// according to its changes"). Every cut of a body with an embedded visual surface cuts that
/// surface with its tets (cutting::hybrid_cut); the result is kept here, immutable and shared,
/// so the render thread takes it from a session snapshot without a lock and without a copy.

#include <memory>
#include <vector>

#include "core/scenario/scenario.h"
#include "simulator/cutting/cut_surface.h"
#include "simulator/cutting/hybrid_cut.h"
#include "simulator/dynamics/body_topology.h"
#include "simulator/world/world.h"

namespace viscera::sim {

/// A body's visible surface after its cuts. mesh.vertices are rest positions (m); the vertex
/// attribute "cut_face" is 1 on the vertices of faces a cut made (the tissue's inside) and
/// "material_x/y/z" hold each vertex's material point, where the organ's solid texture is
/// evaluated; each vertex follows `embedding` in `tets` (the body's tets after the cut, in the
/// world's order).
struct CutVisibleSurface {
  core::SurfaceMesh mesh;
  core::SurfaceEmbedding embedding;
  std::vector<core::Tetrahedron> tets;
};

class VisibleSurfaces {
 public:
  /// Keeps, per body of `world`, its scenario object's surface when that surface is embedded
  /// in the body's tets (SceneObject::embedding, one entry per surface vertex).
  VisibleSurfaces(const core::Scenario& scenario, const World& world);

  /// Body `body`'s surface as cut so far, or null while it is uncut (the scenario's holds).
  const std::shared_ptr<const CutVisibleSurface>& cut_surface(int body) const {
    return cut_[static_cast<std::size_t>(body)];
  }

  /// Cuts body `body` (its rest mesh `mesh`, deformed positions `current`) with `surface`,
  /// cutting its visible surface with it when it has one. When the cut changed the body, the
  /// caller hands the result to World::topology_changed, which keeps the tets' order, so the
  /// new surface's embedding holds.
  cutting::TopologyChange cut(int body, const core::TetMesh& mesh,
                              const std::vector<core::Vec3>& current,
                              const cutting::CutSurface& surface,
                              const cutting::HybridCutOptions& options);

  /// Body `body` lost tets (retired_tissue.h): `topology` keeps the others, in their order, and
  /// names each one's old index in tet_parent. The triangles of the cut surface with a vertex in
  /// a lost tet go with them; the rest keep their places, embedded in the kept tets' new
  /// indices. A body with no cut surface yet is left alone (only cuts make fragments).
  void retire(int body, const BodyTopology& topology);

 private:
  std::vector<const core::SceneObject*> objects_;  ///< per body, null: no embedded surface
  std::vector<std::shared_ptr<const CutVisibleSurface>> cut_;
};

}  // namespace viscera::sim
