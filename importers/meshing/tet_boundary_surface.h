#pragma once
/// The visual surface taken from the tetrahedra's own boundary (issue 20 §2): the outward
/// boundary faces of a Mesh_3 body, on its boundary nodes. Mesh_3 already placed those nodes on
/// the labels' boundary within its facet distance, so the surface costs no contouring,
/// smoothing, decimation or repair; it never crosses itself (its triangles are faces of one
/// valid tetrahedralisation) and embeds exactly (each vertex is a corner of a tet, weight 1).
/// Its resolution is Mesh_3's boundary facets (facet size and distance), coarser than the
/// contour of label_surface.h.

#include "core/mesh/surface_embedding.h"
#include "core/mesh/surface_mesh.h"
#include "core/mesh/tet_mesh.h"

namespace viscera::importers {

/// A visual surface and its embedding in the body it came from.
struct TetBoundarySurface {
  core::SurfaceMesh mesh;  ///< outward, unit vertex normals; vertices in order of first use
  core::SurfaceEmbedding embedding;
};

/// The boundary of `body` (its surface_faces) as a surface of its own, embedded in `body`.
/// Throws core::InputError when the body has no tets or no boundary faces.
TetBoundarySurface tet_boundary_surface(const core::TetMesh& body);

}  // namespace viscera::importers
