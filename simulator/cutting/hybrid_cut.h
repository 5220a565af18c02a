#pragma once
/// The non-progressive hybrid cut of seed 000 §5.1 (Steinemann, Harders, Gross & Székely,
/// "Hybrid cutting of deformable solids", IEEE VR 2006): once the loop has traversed the tissue,
/// the body is cut along the swept surface in one step.
///
/// 1. Node snapping: where the surface crosses a tet edge within `snap_fraction` of its length
///    from an end node, that node is taken onto the cut (it is not moved); the cut then follows
///    existing edges and faces there. Nodes whose crossings disagree, nodes on both sides of an
///    edge the surface does not cross (the cut's border), and cut corners of tets whose
///    decomposition would hold a tet below `min_dihedral_degrees` (either configuration) are
///    snapped too, so no degenerate tet is ever created.
/// 2. Decomposition: each traversed tet with cut edges is split by one of the patterns of
///    tet_decomposition.h; new nodes sit on the cut edges at the crossing, in the deformed and
///    (same edge parameter) the rest configuration. Shared faces split identically.
/// 3. Relaxation: cut_relaxation.h on the conforming mesh (volume unchanged).
/// 4. Node separation: every node on the cut (snapped or new) is duplicated once per group of
///    its tets that stay connected through faces not on the cut (one, two or three separated
///    nodes for a vertex, edge or face lying in the cut; more for the decomposed tets).
/// 5. The new faces become surface faces; masses are recomputed (total mass kept); the visual
///    surface is cut with the tets (visual_surface_cut.h).
/// The total volume is unchanged (to rounding) in both configurations.

#include "simulator/cutting/cut_relaxation.h"
#include "simulator/cutting/cut_surface.h"
#include "simulator/cutting/topology_change.h"

namespace viscera::sim::cutting {

struct HybridCutOptions {
  /// A crossing closer than this fraction of an edge's length to its end snaps that end.
  double snap_fraction = 0.2;
  /// No tet the cut creates has a smallest dihedral angle below this, in degrees.
  double min_dihedral_degrees = 1.0;
  RelaxationOptions relaxation;
};

/// Cuts one body. body.nodes are the rest positions (m), `current` the deformed ones where the
/// cut surface lives; the body's node_mass, fixed and tet_labels (when present) are carried.
/// Throws InputError for a body without tets, `current` of the wrong length or not finite, a
/// cut surface with no triangles, bad indices or non-finite points, or options out of range.
TopologyChange hybrid_cut(const core::TetMesh& body, const std::vector<core::Vec3>& current,
                          const CutSurface& cut, const HybridCutOptions& options = {});

/// The same, also cutting the visual surface embedded in the body (vertices follow their tet;
/// embedding.tet.size() == visual.vertices.size()).
TopologyChange hybrid_cut(const core::TetMesh& body, const std::vector<core::Vec3>& current,
                          const CutSurface& cut, const core::SurfaceMesh& visual,
                          const core::SurfaceEmbedding& embedding,
                          const HybridCutOptions& options = {});

/// Throws InputError when the loop's first or last position along the sweep lies inside the
/// body in its current configuration: the cut is applied only once the loop has traversed the
/// tissue (seed 000 §5.1, "Object meshes are decomposed only once they have been completely
/// traversed").
void require_sweep_leaves_tissue(const core::TetMesh& body, const std::vector<core::Vec3>& current,
                                 const LoopElectrode& loop, const std::vector<LoopPose>& sweep);

}  // namespace viscera::sim::cutting
