#pragma once
/// Label map → simulation-ready body in one call (issue 3 §4): the visual surface of the labels
/// (label_surface.h), their tetrahedra (label_tet_mesher.h), the surface embedded in the tets
/// (tet id and barycentric weights per surface vertex) and the tets' quality report.

#include <map>
#include <string>

#include "core/image/image_volume.h"
#include "core/mesh/surface_embedding.h"
#include "core/mesh/tet_mesh.h"
#include "core/mesh/tet_quality.h"
#include "core/progress.h"
#include "importers/meshing/label_surface.h"
#include "importers/meshing/label_tet_mesher.h"

namespace viscera::importers {

/// Where the visual surface comes from (issue 20 §2).
enum class VisualSurfaceSource {
  /// The tets' boundary (tet_boundary_surface.h): no extra work, exact embedding, Mesh_3's
  /// boundary resolution.
  TetBoundary,
  /// The label's own contour (label_surface.h): flying edges, smoothing, decimation to
  /// surface.target_triangles and repair, on a thread beside Mesh_3, then embedded.
  LabelContour,
};

/// Options of the whole pipeline; `tets.label` also selects the surface's label.
struct LabelBodyOptions {
  /// The library keeps the contour (callers such as the studio offer its triangle budget);
  /// `viscera mesh tets` defaults to the tets' boundary (--surface).
  VisualSurfaceSource visual_surface = VisualSurfaceSource::LabelContour;
  LabelSurfaceOptions surface;
  LabelTetMeshingOptions tets;
  core::TetQualityOptions quality;
  /// LabelContour: extract the visual surface on a thread of its own while Mesh_3 runs (both
  /// are deterministic, so the result is the same; on 2 cores sequential Mesh_3 beside the
  /// surface uses both).
  bool concurrent_surface = true;
  /// Wall-clock budget of the whole pipeline, s (0: none). When it runs out every stage stops
  /// at its next cancellation point and mesh_label_body throws core::ValidationError naming the
  /// stage and the budget (a Progress the caller passed is then cancelled too).
  double time_limit_seconds = 0.0;
};

/// A body made from a label map.
struct LabelBody {
  LabelSurface surface;              ///< visual surface (outer surface of the meshed labels)
  core::TetMesh body;                ///< tets with labels and boundary faces
  core::SurfaceEmbedding embedding;  ///< of surface.mesh's vertices in body
  core::TetQualityReport quality;
  ResolvedTetCriteria criteria;  ///< Mesh_3 criteria used, m
  /// Wall-clock seconds per stage: "surface", "tets", "embedding", "quality", "total", and the
  /// contour's steps as "surface.contour" … (stages overlap with concurrent_surface).
  std::map<std::string, double> seconds;
};

/// Runs the pipeline on `labels`. Throws as label_surface() and mesh_label_map(), and
/// core::ValidationError when options.time_limit_seconds runs out.
LabelBody mesh_label_body(const core::LabelMap& labels, const LabelBodyOptions& options,
                          const std::string& what,
                          core::Progress& progress = core::Progress::none());

/// Largest distance in m between a surface vertex and its position rebuilt from the embedding
/// on the body's rest nodes: the embedding's reconstruction error.
double embedding_error(const core::SurfaceMesh& surface, const core::SurfaceEmbedding& embedding,
                       const core::TetMesh& body);

}  // namespace viscera::importers
