#pragma once
/// Closed surface → tetrahedral mesh with gmsh's Delaunay mesher and its optimisers, with an
/// optional size field that grades the tets from the surface's edge length to a coarser core.

#include "core/mesh/surface_mesh.h"
#include "core/mesh/tet_mesh.h"
#include "core/progress.h"

namespace viscera::core {

/// Options for tetrahedral meshing of a closed surface.
struct TetMeshingOptions {
  double cell_size = 0.0;  ///< target edge length inside the volume in m; 0 = from the surface
  bool optimize = true;    ///< gmsh's tetrahedral optimisation (removes slivers)
  int random_seed = 1;     ///< gmsh's Mesh.RandomSeed, fixed for byte-identical output
  /// Size field (gmsh Distance + Threshold fields): target edge length `surface_size` at the
  /// boundary, growing linearly to `cell_size` at `grading_distance` inside (m). 0 = no field:
  /// sizes grow from the surface's edges to cell_size as gmsh sees fit.
  double grading_distance = 0.0;
  /// Edge length at the boundary for the size field, m; 0 = the surface's mean edge length.
  double surface_size = 0.0;
  /// gmsh improves tets whose quality (gamma, 0…1) is below this (gmsh's default 0.3).
  double optimize_threshold = 0.3;
};

/// Fills the volume bounded by `surface` with tetrahedra. The surface triangles are kept as
/// the boundary of the result (so they become TetMesh::surface_faces, oriented outward); the
/// result has positive tets, no masses and no fixed nodes.
/// Throws InputError when the surface is not closed and consistently oriented, and when gmsh
/// refuses it (self-intersections: "PLC Error"); CancelledError through `progress`.
/// gmsh keeps global state: calls are serialised inside.
TetMesh mesh_closed_surface(const SurfaceMesh& surface, const TetMeshingOptions& options = {},
                            Progress& progress = Progress::none());

/// Fills the region inside `outer` and outside every surface in `holes` with tetrahedra — a
/// hollow shell such as the wall between an organ's outer and inner layer (seed 001 §3.3). Each
/// boundary is a closed, outward-oriented surface of its own, the holes lie inside `outer` and
/// do not touch it or each other. Nodes: outer's vertices, then each hole's, then the interior
/// ones; surface_faces: outer's triangles, then each hole's reversed (outward from the material).
/// Throws as mesh_closed_surface, naming the boundary at fault.
TetMesh mesh_region_between(const SurfaceMesh& outer, const std::vector<SurfaceMesh>& holes,
                            const TetMeshingOptions& options = {},
                            Progress& progress = Progress::none());

}  // namespace viscera::core
