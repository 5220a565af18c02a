#pragma once
/// The visual surface cut with the tets (seed 000 §9: the high-resolution surface "is mapped to
/// the lower resolution tetrahedral model and updated according to its changes"). Internal to
/// simulator/cutting; hybrid_cut calls it when it is given a visual surface.
///
/// Visual vertices are re-embedded in the piece of their old tet that holds their material
/// (rest) point. A visual triangle whose edges cross the cut surface twice is split along the
/// crossing, each side getting its own copies of the crossing points; the tet faces that became
/// surface on the cut are added as visual triangles (listed in visual_cut_triangles, vertex
/// attribute "cut_face" = 1). Every vertex gets its material position in the attributes
/// "material_x/y/z" so the view can colour cut faces from the organ's solid texture, which is
/// defined in space (textures/solid_texture.h).

#include "core/mesh/surface_embedding.h"
#include "simulator/cutting/cut_surface_index.h"
#include "simulator/cutting/topology_change.h"

namespace viscera::sim::cutting {

/// Fills change.visual, change.visual_embedding and change.visual_cut_triangles. body: the
/// body before the cut (rest nodes); old_current: its deformed positions.
void cut_visual_surface(const core::SurfaceMesh& visual, const core::SurfaceEmbedding& embedding,
                        const core::TetMesh& body, const std::vector<core::Vec3>& old_current,
                        const CutSurfaceIndex& index, TopologyChange& change);

}  // namespace viscera::sim::cutting
